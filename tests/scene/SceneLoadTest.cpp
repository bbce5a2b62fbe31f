// Scene loading without GL: valid files load with the right content, and malformed ones built
// inline (defects the generated corpus does not cover) fail with SceneInvalid / SceneLoadFailed
// and a message naming the file and the problem, logged exactly once.
#include "scene_fixtures.hpp"
#include "support/log_capture.hpp"

#include "scene.hpp"
#include "scene_state.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>

namespace rrc::test {
namespace {

using scene::loadScene;
using json = nlohmann::json;

const std::string kData = RRC_SCENE_TEST_DATA;
const std::string kAssets = RRC_SCENE_ASSETS;

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return s;
}

// Loads `path` expecting failure with `id`, a message naming the file and containing `word`
// (case-insensitive), and exactly one logged error.
void expectRejected(const std::string& path, LogId id, const std::string& word, const scene::LoadOptions& options = {}) {
    LogCapture log;
    auto result = loadScene(path, options);
    ASSERT_FALSE(result.ok()) << path << " loaded";
    EXPECT_EQ(result.error().id, id) << result.error().message;
    const std::string message = result.error().message;
    EXPECT_NE(message.find(std::filesystem::path(path).filename().string()), std::string::npos) << message;
    EXPECT_NE(lower(message).find(lower(word)), std::string::npos) << "'" << word << "' not in: " << message;
    ASSERT_EQ(log.items.size(), 1u);
    EXPECT_EQ(log.items[0].id, id);
    EXPECT_EQ(log.items[0].message, message);
}

void expectTriangle(const scene::Scene& s) {
    ASSERT_EQ(s.meshes.size(), 1u);
    ASSERT_EQ(s.meshes[0].primitives.size(), 1u);
    const scene::Primitive& p = s.meshes[0].primitives[0];
    EXPECT_EQ(p.positions, (std::vector<glm::vec3>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}));
    EXPECT_EQ(p.normals, (std::vector<glm::vec3>(3, glm::vec3(0, 0, 1))));
    EXPECT_EQ(p.uv0, (std::vector<glm::vec2>{{0, 1}, {1, 1}, {0, 0}}));
    EXPECT_EQ(p.indices, (std::vector<uint32_t>{0, 1, 2}));
    EXPECT_TRUE(p.tangents.empty() && p.joints.empty() && p.weights.empty());
    EXPECT_EQ(p.boundsMax, glm::vec3(1, 1, 0));
    ASSERT_EQ(p.material, 0);
    EXPECT_EQ(s.materials[0].baseColorFactor, glm::vec4(0.8f, 0.1f, 0.1f, 1.0f));
    EXPECT_EQ(s.materials[0].baseColorTexture.texture, scene::kNone);
    EXPECT_EQ(s.roots, (std::vector<uint32_t>{0}));
    ASSERT_EQ(s.nodes.size(), 1u);
    EXPECT_EQ(s.nodes[0].mesh, 0);
    EXPECT_EQ(s.nodes[0].local.toMatrix(), glm::dmat4(1.0));
}

TEST(SceneLoad, GoodTriangleGltf) {
    const std::string path = kData + "/good_triangle.gltf";
    if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " not generated (scripts/make_bad_gltf.py)";
    LogCapture log;
    auto s = loadScene(path);
    ASSERT_TRUE(s.ok()) << s.error().message;
    expectTriangle(s.value());
    EXPECT_TRUE(log.items.empty());
}

TEST(SceneLoad, GoodTriangleGlb) {
    const std::string path = kData + "/good_triangle.glb";
    if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " not generated (scripts/make_bad_gltf.py)";
    auto s = loadScene(path);
    ASSERT_TRUE(s.ok()) << s.error().message;
    expectTriangle(s.value());
}

TEST(SceneLoad, InlineTriangleWithExternalBuffer) {
    TempDir dir;
    json doc = triangleDocument();
    // Move buffer 0 (positions) into a file next to the document.
    const std::vector<float> positions{0, 0, 0, 1, 0, 0, 0, 1, 0};
    dir.write("data/tri positions.bin", bytesOf(positions));
    doc["buffers"][0]["uri"] = "data/tri%20positions.bin";
    auto s = loadScene(dir.write("tri.gltf", doc));
    ASSERT_TRUE(s.ok()) << s.error().message;
    expectTriangle(s.value());
}

TEST(SceneLoad, TexturedTempleAsset) {
    auto s = loadScene(kAssets + "/temple.glb");
    ASSERT_TRUE(s.ok()) << s.error().message;
    const scene::Scene& t = s.value();
    EXPECT_EQ(t.nodes.size(), 82u);
    ASSERT_EQ(t.images.size(), 2u);
    for (const auto& image : t.images) {
        EXPECT_EQ(image.width, 256);
        EXPECT_EQ(image.height, 256);
        EXPECT_EQ(image.rgba.size(), 256u * 256u * 4u);
    }
    ASSERT_EQ(t.cameras.size(), 1u);
    EXPECT_DOUBLE_EQ(t.cameras[0].yfov, 0.9);
    const scene::Material& ground = t.materials[0];
    EXPECT_GE(ground.baseColorTexture.texture, 0);
    EXPECT_GE(ground.normalTexture.texture, 0);
    EXPECT_FALSE(t.meshes[0].primitives[0].tangents.empty());
    EXPECT_EQ(t.samplers[0].minFilter, 9987);  // LINEAR_MIPMAP_LINEAR
    EXPECT_EQ(t.order.size(), t.nodes.size());
}

TEST(SceneLoad, SkinnedCharacterAsset) {
    auto s = loadScene(kAssets + "/character.glb");
    ASSERT_TRUE(s.ok()) << s.error().message;
    const scene::Scene& c = s.value();
    ASSERT_EQ(c.skins.size(), 1u);
    EXPECT_EQ(c.skins[0].joints.size(), 15u);
    EXPECT_EQ(c.skins[0].inverseBind.size(), 15u);
    ASSERT_EQ(c.animations.size(), 1u);
    EXPECT_EQ(c.animations[0].name, "run");
    EXPECT_GT(c.animations[0].end, c.animations[0].start);
    EXPECT_FALSE(c.animations[0].channels.empty());
    const scene::Primitive& p = c.meshes[0].primitives[0];
    EXPECT_EQ(p.joints.size(), p.positions.size());
    EXPECT_EQ(p.weights.size(), p.positions.size());
}

// --- malformed input built inline ---------------------------------------------------------------

class SceneLoadDefect : public ::testing::Test {
protected:
    TempDir dir;
    json doc = triangleDocument();
    std::string write() { return dir.write("defect.gltf", doc); }
};

TEST_F(SceneLoadDefect, MissingSceneFile) {
    expectRejected((dir.path() / "nothing_here.gltf").string(), LogId::SceneLoadFailed, "does not exist");
}

TEST_F(SceneLoadDefect, PercentEncodedParentSegment) {
    doc["buffers"][0]["uri"] = "%2e%2e/secret.bin";
    expectRejected(write(), LogId::SceneInvalid, "uri");
}

TEST_F(SceneLoadDefect, SymlinkLeavingTheFolder) {
    TempDir outside;
    const std::string target = outside.write("positions.bin", bytesOf(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0}));
    std::filesystem::create_symlink(target, dir.path() / "link.bin");
    doc["buffers"][0]["uri"] = "link.bin";
    expectRejected(write(), LogId::SceneInvalid, "outside the scene's folder");
}

TEST_F(SceneLoadDefect, BufferFileSizeMismatch) {
    dir.write("short.bin", std::string(20, '\0'));
    doc["buffers"][0]["uri"] = "short.bin";
    expectRejected(write(), LogId::SceneInvalid, "byteLength says 36");
}

TEST_F(SceneLoadDefect, DataUriWithBadCharacter) {
    doc["buffers"][0]["uri"] = "data:application/octet-stream;base64,AAAA*AAA";
    expectRejected(write(), LogId::SceneInvalid, "base64");
}

TEST_F(SceneLoadDefect, CountMismatchBetweenAttributes) {
    doc["accessors"][1]["count"] = 2;
    expectRejected(write(), LogId::SceneInvalid, "differs from the POSITION count");
}

TEST_F(SceneLoadDefect, WrongComponentTypeForPositions) {
    doc["accessors"][0]["componentType"] = kUShort;
    expectRejected(write(), LogId::SceneInvalid, "not allowed here");
}

TEST_F(SceneLoadDefect, NonTriangleMode) {
    doc["meshes"][0]["primitives"][0]["mode"] = 1;
    expectRejected(write(), LogId::SceneInvalid, "mode 1");
}

TEST_F(SceneLoadDefect, SceneNodeThatIsNotARoot) {
    doc["nodes"] = {{{"children", {1}}}, {{"mesh", 0}}};
    doc["scenes"][0]["nodes"] = {0, 1};
    expectRejected(write(), LogId::SceneInvalid, "must be roots");
}

TEST_F(SceneLoadDefect, RequiredExtension) {
    doc["extensionsRequired"] = {"KHR_draco_mesh_compression"};
    expectRejected(write(), LogId::SceneInvalid, "extension");
}

TEST_F(SceneLoadDefect, NestedTooDeep) {
    json deep = json::array();
    for (int i = 0; i < 200; ++i) deep = json::array({deep});
    doc["extras"] = deep;  // tinygltf would convert this recursively
    expectRejected(write(), LogId::SceneInvalid, "nested deeper");
}

TEST_F(SceneLoadDefect, ByteBudget) {
    expectRejected(write(), LogId::SceneInvalid, "over the load limit", {.maxBytes = 512});
}

TEST_F(SceneLoadDefect, JsonSizeLimit) {
    expectRejected(write(), LogId::SceneInvalid, "over the limit", {.maxJsonBytes = 100});
}

// A 100000-node chain whose last node points back at the first: found, and in linear time (a
// per-node walk to the root would take ~5e9 steps here).
TEST_F(SceneLoadDefect, CycleAtTheEndOfALongChain) {
    constexpr int kNodes = 100000;
    doc["nodes"] = json::array();
    for (int i = 0; i < kNodes; ++i) doc["nodes"].push_back({{"children", {(i + 1) % kNodes}}});
    doc["scenes"][0]["nodes"] = json::array();
    expectRejected(write(), LogId::SceneInvalid, "cycle");
}

TEST(SceneLoad, LongChainOfNodes) {
    constexpr int kNodes = 100000;
    TempDir dir;
    json doc = triangleDocument();
    doc["nodes"] = json::array();
    for (int i = 0; i < kNodes; ++i) {
        json node = {{"translation", {0.5, 0.0, 0.0}}};
        if (i + 1 < kNodes) node["children"] = {i + 1};
        else node["mesh"] = 0;
        doc["nodes"].push_back(node);
    }
    auto s = loadScene(dir.write("chain.gltf", doc));
    ASSERT_TRUE(s.ok()) << s.error().message;
    EXPECT_EQ(s.value().order.size(), size_t(kNodes));
    EXPECT_EQ(s.value().nodes.back().parent, kNodes - 2);
    const scene::SceneState state(s.value());
    EXPECT_DOUBLE_EQ(state.world().back()[3].x, 0.5 * kNodes);  // exact: sums of halves in double
}

TEST_F(SceneLoadDefect, ImageThatIsNotPngOrJpeg) {
    const std::string text = "this is not an image";
    doc["images"] = {{{"uri", "data:image/png;base64," + base64(text.data(), text.size())}}};
    doc["textures"] = {{{"source", 0}}};
    expectRejected(write(), LogId::SceneInvalid, "not a PNG or JPEG");
}

TEST_F(SceneLoadDefect, ImageFileMissing) {
    doc["images"] = {{{"uri", "missing.png"}}};
    expectRejected(write(), LogId::SceneLoadFailed, "missing.png");
}

// Node 0 is skinned by skin 0 (one joint, node 1) but a vertex names joint 2.
TEST_F(SceneLoadDefect, JointIndexBeyondTheSkin) {
    const int joints = addAccessor(doc, std::vector<uint8_t>{0, 0, 0, 0, 0, 0, 0, 0, 2, 0, 0, 0}, kUByte, "VEC4", 3);
    const int weights = addAccessor(doc, std::vector<float>{1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0}, kFloat, "VEC4", 3);
    doc["meshes"][0]["primitives"][0]["attributes"]["JOINTS_0"] = joints;
    doc["meshes"][0]["primitives"][0]["attributes"]["WEIGHTS_0"] = weights;
    doc["nodes"] = {{{"mesh", 0}, {"skin", 0}}, {{"name", "joint"}}};
    doc["scenes"][0]["nodes"] = {0, 1};
    doc["skins"] = {{{"joints", {1}}}};
    expectRejected(write(), LogId::SceneInvalid, "uses joint 2");
}

TEST_F(SceneLoadDefect, AnimatedNodeWithMatrix) {
    const int input = addAccessor(doc, std::vector<float>{0, 1}, kFloat, "SCALAR", 2);
    const int output = addAccessor(doc, std::vector<float>{0, 0, 0, 1, 0, 0}, kFloat, "VEC3", 2);
    doc["nodes"][0]["matrix"] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    doc["animations"] = {{{"samplers", {{{"input", input}, {"output", output}}}},
                          {"channels", {{{"sampler", 0}, {"target", {{"node", 0}, {"path", "translation"}}}}}}}};
    expectRejected(write(), LogId::SceneInvalid, "has a matrix");
}

TEST_F(SceneLoadDefect, KeyTimesGoingBackwards) {
    const int input = addAccessor(doc, std::vector<float>{1, 0}, kFloat, "SCALAR", 2);
    const int output = addAccessor(doc, std::vector<float>{0, 0, 0, 1, 0, 0}, kFloat, "VEC3", 2);
    doc["animations"] = {{{"samplers", {{{"input", input}, {"output", output}}}},
                          {"channels", {{{"sampler", 0}, {"target", {{"node", 0}, {"path", "translation"}}}}}}}};
    expectRejected(write(), LogId::SceneInvalid, "before the previous key");
}

TEST_F(SceneLoadDefect, CubicSplineOutputCount) {
    const int input = addAccessor(doc, std::vector<float>{0, 1}, kFloat, "SCALAR", 2);
    const int output = addAccessor(doc, std::vector<float>{0, 0, 0, 1, 0, 0}, kFloat, "VEC3", 2);
    doc["animations"] = {{{"samplers", {{{"input", input}, {"output", output}, {"interpolation", "CUBICSPLINE"}}}},
                          {"channels", {{{"sampler", 0}, {"target", {{"node", 0}, {"path", "translation"}}}}}}}};
    expectRejected(write(), LogId::SceneInvalid, "3 per key");
}

TEST_F(SceneLoadDefect, IndexNotAnInteger) {
    doc["nodes"][0]["mesh"] = 0.5;
    expectRejected(write(), LogId::SceneInvalid, "invalid index");
}

TEST_F(SceneLoadDefect, IndexArrayNotAnArray) {
    doc["meshes"][0]["primitives"][0]["indices"] = json::object({{"bufferView", 3}});
    expectRejected(write(), LogId::SceneInvalid, "indices");
}

TEST(SceneLoad, CubicSplineAnimationLoads) {
    TempDir dir;
    json doc = triangleDocument();
    const int input = addAccessor(doc, std::vector<float>{0, 1}, kFloat, "SCALAR", 2);
    const int output = addAccessor(doc, std::vector<float>(18, 0.0f), kFloat, "VEC3", 6);
    doc["animations"] = {{{"samplers", {{{"input", input}, {"output", output}, {"interpolation", "CUBICSPLINE"}}}},
                          {"channels", {{{"sampler", 0}, {"target", {{"node", 0}, {"path", "scale"}}}}}}}};
    auto s = loadScene(dir.write("cubic.gltf", doc));
    ASSERT_TRUE(s.ok()) << s.error().message;
    ASSERT_EQ(s.value().animations.size(), 1u);
    EXPECT_EQ(s.value().animations[0].samplers[0].interpolation, scene::Interpolation::CubicSpline);
    EXPECT_EQ(s.value().animations[0].samplers[0].values.size(), 6u);
}

} // namespace
} // namespace rrc::test
