// A glTF 2.0 scene as plain CPU data: meshes, materials, RGBA8 images, the node hierarchy,
// skins, animation clips and cameras. loadScene() validates everything it reads, so a Scene
// that exists is safe to upload and draw (no reference or index is out of range).
#pragma once
#include <rrc/result.hpp>

#include <glm/ext/vector_uint4_sized.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace rrc::scene {

// Indices into Scene's arrays; -1 means "none", as in glTF.
inline constexpr int kNone = -1;

struct Primitive {
    std::vector<glm::vec3> positions;       // always present
    std::vector<glm::vec3> normals;         // empty when the file has none
    std::vector<glm::vec2> uv0;             // empty when absent; normalized integers converted
    std::vector<glm::vec4> tangents;        // empty when absent (xyz, w = bitangent sign)
    std::vector<glm::u16vec4> joints;       // JOINTS_0, empty when absent; < the skin's joint count
    std::vector<glm::vec4> weights;         // WEIGHTS_0, empty when absent
    std::vector<uint32_t> indices;          // triangles; generated 0..n-1 for non-indexed primitives
    int material = kNone;
    glm::vec3 boundsMin{0.0f}, boundsMax{0.0f};
};

struct Mesh {
    std::string name;
    std::vector<Primitive> primitives;
};

struct TextureRef {
    int texture = kNone;   // index into Scene::textures
    int texCoord = 0;      // only set 0 (TEXCOORD_0) is loaded
    float scale = 1.0f;    // normalTexture.scale
};

enum class AlphaMode { Opaque, Mask, Blend };

struct Material {
    std::string name;
    glm::vec4 baseColorFactor{1.0f};
    TextureRef baseColorTexture;            // sRGB
    TextureRef normalTexture;               // linear, tangent space
    float metallicFactor = 1.0f, roughnessFactor = 1.0f;
    glm::vec3 emissiveFactor{0.0f};
    AlphaMode alphaMode = AlphaMode::Opaque;
    float alphaCutoff = 0.5f;
    bool doubleSided = false;
};

// GL enum values from the file; 0 = not given (the uploader picks its default).
struct Sampler {
    int magFilter = 0, minFilter = 0;
    int wrapS = 0x2901, wrapT = 0x2901;     // GL_REPEAT, the glTF default
};

struct GltfTexture {  // a glTF "texture": an image and a sampler (not rrc::Texture, the GL object)
    int image = kNone;
    int sampler = kNone;
};

// Decoded to 8-bit RGBA, rows top-down as stored in the file (glTF's uv (0,0) is the top-left).
struct Image {
    std::string name;
    int width = 0, height = 0;
    std::vector<uint8_t> rgba;
};

// A node's local transform: `matrix` when the file gave one, otherwise T * R * S.
struct Transform {
    glm::dvec3 translation{0.0};
    glm::dquat rotation{1.0, 0.0, 0.0, 0.0};  // glm order (w, x, y, z); glTF stores x, y, z, w
    glm::dvec3 scale{1.0};
    std::optional<glm::dmat4> matrix;
    glm::dmat4 toMatrix() const;
};

struct Node {
    std::string name;
    Transform local;                        // rest pose from the file
    std::vector<uint32_t> children;
    int parent = kNone;
    int mesh = kNone, skin = kNone, camera = kNone;
};

struct Skin {
    std::string name;
    std::vector<uint32_t> joints;           // node indices, unique
    std::vector<glm::dmat4> inverseBind;    // one per joint (identity when the file has none)
    int skeleton = kNone;                   // common root node, if the file names one
};

enum class AnimationPath { Translation, Rotation, Scale };
enum class Interpolation { Linear, Step, CubicSpline };

struct AnimationSampler {
    std::vector<double> times;              // non-decreasing, finite
    // One value per key (Linear, Step) or three (CubicSpline: in-tangent, value, out-tangent);
    // xyz for translation and scale, a quaternion as (x, y, z, w) for rotation.
    std::vector<glm::dvec4> values;
    Interpolation interpolation = Interpolation::Linear;
};

struct AnimationChannel {
    uint32_t sampler = 0;
    uint32_t node = 0;
    AnimationPath path = AnimationPath::Translation;
};

struct Animation {
    std::string name;
    std::vector<AnimationSampler> samplers;
    std::vector<AnimationChannel> channels; // morph-target "weights" channels are dropped
    double start = 0.0, end = 0.0;          // time range over all samplers
};

struct Camera {
    enum class Type { Perspective, Orthographic };
    std::string name;
    Type type = Type::Perspective;
    double yfov = 0.8, aspectRatio = 0.0;   // perspective; aspectRatio 0 = use the viewport's
    double xmag = 1.0, ymag = 1.0;          // orthographic
    double znear = 0.1, zfar = 0.0;         // zfar 0 = infinite (perspective only)
};

struct Scene {
    std::string source;                     // the path it was loaded from (for messages)
    std::vector<Mesh> meshes;
    std::vector<Material> materials;
    std::vector<GltfTexture> textures;
    std::vector<Sampler> samplers;
    std::vector<Image> images;
    std::vector<Node> nodes;
    std::vector<Skin> skins;
    std::vector<Animation> animations;
    std::vector<Camera> cameras;
    std::vector<uint32_t> roots;            // root nodes of the file's default scene
    std::vector<uint32_t> order;            // every node, each after its parent

    // Fills `order` and every node's `parent` from the children lists. For scenes built in code;
    // loadScene() has done it (and rejected cycles and shared children).
    void linkHierarchy();
};

struct LoadOptions {
    uint64_t maxBytes = uint64_t(1) << 30;  // cap on file bytes read plus data decoded, in total
    uint64_t maxJsonBytes = 64u << 20;      // cap on the JSON text (parsed twice, ~10x in memory)
    int maxImageSize = 16384;               // widest / tallest image accepted, in pixels
};

// Loads a .gltf (with its external or data-URI buffers and images) or a .glb. Every reference,
// accessor range and value is checked first; failures return SceneInvalid (malformed content)
// or SceneLoadFailed (I/O) with a message "<path>: <what is wrong where>". Resources are only
// read from the file's own folder or below.
Result<Scene> loadScene(const std::string& path, const LoadOptions& options = {});

// World matrices of all nodes from the given local transforms (double precision).
void computeWorld(const Scene& scene, const std::vector<glm::dmat4>& locals, std::vector<glm::dmat4>& world);

} // namespace rrc::scene
