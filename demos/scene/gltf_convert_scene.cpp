// Materials, textures, samplers, images, nodes (matrix or TRS), the default scene's roots,
// cameras and skins (inverse bind matrices read in double).
#include "gltf_accessor.hpp"
#include "gltf_convert.hpp"

#include <glm/gtc/type_ptr.hpp>

#include <cmath>

namespace rrc::scene::detail {
namespace {

TextureRef textureRef(int index, int texCoord, double scale = 1.0) {
    return TextureRef{.texture = index, .texCoord = texCoord, .scale = float(scale)};
}

AlphaMode alphaMode(const std::string& mode) {
    return mode == "MASK" ? AlphaMode::Mask : mode == "BLEND" ? AlphaMode::Blend : AlphaMode::Opaque;
}

Transform transform(const tinygltf::Node& node) {
    Transform t;
    if (node.matrix.size() == 16) {
        t.matrix = glm::make_mat4(node.matrix.data());  // both column-major
        return t;
    }
    if (node.translation.size() == 3) t.translation = glm::make_vec3(node.translation.data());
    if (node.scale.size() == 3) t.scale = glm::make_vec3(node.scale.data());
    if (node.rotation.size() == 4)  // glTF (x, y, z, w); validation rejected the zero quaternion
        t.rotation = glm::normalize(glm::dquat(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]));
    return t;
}

} // namespace

void convertMaterials(tinygltf::Model& model, Scene& scene) {
    for (const tinygltf::Material& m : model.materials) {
        const auto& pbr = m.pbrMetallicRoughness;
        Material out;
        out.name = m.name;
        out.baseColorFactor = glm::vec4(glm::make_vec4(pbr.baseColorFactor.data()));
        out.baseColorTexture = textureRef(pbr.baseColorTexture.index, pbr.baseColorTexture.texCoord);
        out.normalTexture = textureRef(m.normalTexture.index, m.normalTexture.texCoord, m.normalTexture.scale);
        out.metallicFactor = float(pbr.metallicFactor);
        out.roughnessFactor = float(pbr.roughnessFactor);
        if (m.emissiveFactor.size() == 3) out.emissiveFactor = glm::vec3(glm::make_vec3(m.emissiveFactor.data()));
        out.alphaMode = alphaMode(m.alphaMode);
        out.alphaCutoff = float(m.alphaCutoff);
        out.doubleSided = m.doubleSided;
        scene.materials.push_back(std::move(out));
    }
    for (const tinygltf::Texture& t : model.textures) scene.textures.push_back({.image = t.source, .sampler = t.sampler});
    for (const tinygltf::Sampler& s : model.samplers)
        scene.samplers.push_back({.magFilter = std::max(s.magFilter, 0), .minFilter = std::max(s.minFilter, 0),
                                  .wrapS = s.wrapS, .wrapT = s.wrapT});
    for (tinygltf::Image& image : model.images)
        scene.images.push_back({.name = image.name, .width = image.width, .height = image.height, .rgba = std::move(image.image)});
}

void convertNodes(const tinygltf::Model& model, Scene& scene) {
    for (const tinygltf::Node& n : model.nodes) {
        Node node;
        node.name = n.name;
        node.local = transform(n);
        node.children.assign(n.children.begin(), n.children.end());
        node.mesh = n.mesh;
        node.skin = n.skin;
        node.camera = n.camera;
        scene.nodes.push_back(std::move(node));
    }
    scene.linkHierarchy();
    const int chosen = model.defaultScene >= 0 ? model.defaultScene : model.scenes.empty() ? -1 : 0;
    if (chosen >= 0) {
        scene.roots.assign(model.scenes[size_t(chosen)].nodes.begin(), model.scenes[size_t(chosen)].nodes.end());
    } else {  // no scenes at all: show every root node rather than nothing
        for (size_t i = 0; i < scene.nodes.size(); ++i)
            if (scene.nodes[i].parent < 0) scene.roots.push_back(uint32_t(i));
    }
    for (const tinygltf::Camera& c : model.cameras) {
        Camera camera{.name = c.name};
        if (c.type == "orthographic") {
            camera.type = Camera::Type::Orthographic;
            camera.xmag = c.orthographic.xmag;
            camera.ymag = c.orthographic.ymag;
            camera.znear = c.orthographic.znear;
            camera.zfar = c.orthographic.zfar;
        } else {
            camera.yfov = c.perspective.yfov;
            camera.aspectRatio = c.perspective.aspectRatio;
            camera.znear = c.perspective.znear;
            camera.zfar = c.perspective.zfar;
        }
        scene.cameras.push_back(std::move(camera));
    }
}

Result<void> convertSkins(const tinygltf::Model& model, Scene& scene, LoadContext& context) {
    for (size_t s = 0; s < model.skins.size(); ++s) {
        const tinygltf::Skin& in = model.skins[s];
        Skin skin{.name = in.name, .joints = {in.joints.begin(), in.joints.end()}, .skeleton = in.skeleton};
        skin.inverseBind.assign(skin.joints.size(), glm::dmat4(1.0));
        if (in.inverseBindMatrices >= 0) {
            const std::string use = "inverseBindMatrices of skin " + std::to_string(s);
            auto view = viewAccessor(model, in.inverseBindMatrices, use, TINYGLTF_TYPE_MAT4,
                                     {{TINYGLTF_COMPONENT_TYPE_FLOAT, false}});
            if (!view) return view.error();
            const std::string what = describeAccessor(in.inverseBindMatrices, use);
            if (view.value().count < skin.joints.size())
                return invalid(what + ": count " + std::to_string(view.value().count) + " < " +
                               std::to_string(skin.joints.size()) + " joints");
            if (!context.charge(uint64_t(skin.joints.size()) * sizeof(glm::dmat4), what)) return invalid(context.budgetError);
            for (size_t j = 0; j < skin.joints.size(); ++j)
                for (int e = 0; e < 16; ++e) {
                    const double value = view.value().get(j, e);
                    if (!std::isfinite(value)) return invalid(what + ": matrix " + std::to_string(j) + " is not finite");
                    skin.inverseBind[j][e / 4][e % 4] = value;
                }
        }
        scene.skins.push_back(std::move(skin));
    }
    return {};
}

} // namespace rrc::scene::detail
