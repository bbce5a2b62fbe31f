// Reference, layout and hierarchy checks on the tinygltf model, in dependency order: accessors,
// meshes, materials/textures/samplers/images, cameras, nodes, scenes, skins, animations.
#include "gltf_validate.hpp"

#include "gltf_accessor.hpp"

#include <algorithm>
#include <cmath>
#include <set>

namespace rrc::scene::detail {
namespace {

bool inRange(int index, size_t count) { return index >= 0 && size_t(index) < count; }

// "mesh 5 does not exist (1 meshes)" unless index is -1 (absent) or valid.
Result<void> checkRef(const std::string& where, const char* kind, int index, size_t count, bool optional = true) {
    if ((optional && index == -1) || inRange(index, count)) return {};
    return invalid(where + ": " + kind + " " + std::to_string(index) + " does not exist (" + std::to_string(count) + " " +
                   kind + (count == 1 ? "" : "s") + ")");
}

bool allFinite(const std::vector<double>& values) {
    return std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); });
}

Result<void> checkVector(const std::string& where, const char* name, const std::vector<double>& values,
                         std::initializer_list<size_t> sizes) {
    if (std::find(sizes.begin(), sizes.end(), values.size()) == sizes.end())
        return invalid(where + ": " + name + " has " + std::to_string(values.size()) + " elements");
    if (!allFinite(values)) return invalid(where + ": " + name + " is not finite");
    return {};
}

Result<void> checkMeshes(const tinygltf::Model& m) {
    for (size_t i = 0; i < m.meshes.size(); ++i) {
        const std::string mesh = "mesh " + std::to_string(i);
        if (m.meshes[i].primitives.empty()) return invalid(mesh + " has no primitives");
        for (size_t p = 0; p < m.meshes[i].primitives.size(); ++p) {
            const tinygltf::Primitive& prim = m.meshes[i].primitives[p];
            const std::string where = mesh + " primitive " + std::to_string(p);
            if (prim.mode != TINYGLTF_MODE_TRIANGLES && prim.mode != -1)
                return invalid(where + ": mode " + std::to_string(prim.mode) + " is not supported (only TRIANGLES, 4)");
            if (!prim.attributes.count("POSITION")) return invalid(where + " has no POSITION attribute");
            if (auto r = checkRef(where, "material", prim.material, m.materials.size()); !r) return r;
            for (const auto& [name, accessor] : prim.attributes)
                if (auto r = checkRef(where + " attribute " + name, "accessor", accessor, m.accessors.size(), false); !r) return r;
            for (const auto& target : prim.targets)
                for (const auto& [name, accessor] : target)
                    if (auto r = checkRef(where + " morph target " + name, "accessor", accessor, m.accessors.size(), false); !r) return r;
        }
    }
    return {};
}

Result<void> checkTextureRef(const std::string& where, const char* slot, int texture, int texCoord, size_t count) {
    if (auto r = checkRef(where + " " + slot, "texture", texture, count); !r) return r;
    if (texCoord < 0) return invalid(where + " " + slot + ": texCoord " + std::to_string(texCoord) + " is negative");
    return {};
}

Result<void> checkMaterials(const tinygltf::Model& m) {
    for (size_t i = 0; i < m.materials.size(); ++i) {
        const tinygltf::Material& mat = m.materials[i];
        const std::string where = "material " + std::to_string(i) + (mat.name.empty() ? "" : " (" + mat.name + ")");
        const auto& pbr = mat.pbrMetallicRoughness;
        const size_t n = m.textures.size();
        for (auto r : {checkTextureRef(where, "baseColorTexture", pbr.baseColorTexture.index, pbr.baseColorTexture.texCoord, n),
                       checkTextureRef(where, "metallicRoughnessTexture", pbr.metallicRoughnessTexture.index,
                                       pbr.metallicRoughnessTexture.texCoord, n),
                       checkTextureRef(where, "normalTexture", mat.normalTexture.index, mat.normalTexture.texCoord, n),
                       checkTextureRef(where, "occlusionTexture", mat.occlusionTexture.index, mat.occlusionTexture.texCoord, n),
                       checkTextureRef(where, "emissiveTexture", mat.emissiveTexture.index, mat.emissiveTexture.texCoord, n),
                       checkVector(where, "baseColorFactor", pbr.baseColorFactor, {4}),
                       checkVector(where, "emissiveFactor", mat.emissiveFactor, {0, 3}),
                       checkVector(where, "factors", {pbr.metallicFactor, pbr.roughnessFactor, mat.alphaCutoff,
                                                      mat.normalTexture.scale}, {4})})
            if (!r) return r;
        if (mat.alphaMode != "OPAQUE" && mat.alphaMode != "MASK" && mat.alphaMode != "BLEND")
            return invalid(where + ": alphaMode '" + mat.alphaMode + "' is not OPAQUE, MASK or BLEND");
    }
    for (size_t i = 0; i < m.textures.size(); ++i) {
        const std::string where = "texture " + std::to_string(i);
        if (auto r = checkRef(where, "image", m.textures[i].source, m.images.size()); !r) return r;
        if (auto r = checkRef(where, "sampler", m.textures[i].sampler, m.samplers.size()); !r) return r;
    }
    const std::set<int> mag{-1, 9728, 9729}, min{-1, 9728, 9729, 9984, 9985, 9986, 9987}, wrap{33071, 33648, 10497};
    for (size_t i = 0; i < m.samplers.size(); ++i) {
        const tinygltf::Sampler& s = m.samplers[i];
        if (!mag.count(s.magFilter) || !min.count(s.minFilter) || !wrap.count(s.wrapS) || !wrap.count(s.wrapT))
            return invalid("sampler " + std::to_string(i) + ": invalid filter or wrap mode (mag " + std::to_string(s.magFilter) +
                           ", min " + std::to_string(s.minFilter) + ", wrap " + std::to_string(s.wrapS) + "/" +
                           std::to_string(s.wrapT) + ")");
    }
    for (size_t i = 0; i < m.images.size(); ++i) {
        const tinygltf::Image& image = m.images[i];
        if (image.image.empty() || image.component != 4 || image.bits != 8 ||
            image.image.size() != size_t(image.width) * size_t(image.height) * 4)
            return invalid("image " + std::to_string(i) + (image.uri.empty() ? "" : " ('" + image.uri + "')") + " was not decoded");
    }
    return {};
}

Result<void> checkCameras(const tinygltf::Model& m) {
    for (size_t i = 0; i < m.cameras.size(); ++i) {
        const tinygltf::Camera& c = m.cameras[i];
        const std::string where = "camera " + std::to_string(i);
        if (c.type == "perspective") {
            const auto& p = c.perspective;
            if (!allFinite({p.yfov, p.znear, p.zfar, p.aspectRatio}) || p.yfov <= 0 || p.znear <= 0 ||
                (p.zfar != 0 && p.zfar <= p.znear) || p.aspectRatio < 0)
                return invalid(where + ": invalid perspective (yfov > 0, znear > 0, zfar 0 or > znear, aspectRatio >= 0)");
        } else if (c.type == "orthographic") {
            const auto& o = c.orthographic;
            if (!allFinite({o.xmag, o.ymag, o.znear, o.zfar}) || o.xmag == 0 || o.ymag == 0 || o.znear < 0 || o.zfar <= o.znear)
                return invalid(where + ": invalid orthographic projection (xmag, ymag nonzero, 0 <= znear < zfar)");
        } else {
            return invalid(where + ": type '" + c.type + "' is not perspective or orthographic");
        }
    }
    return {};
}

Result<void> checkNodes(const tinygltf::Model& m, std::vector<int>& parent) {
    const size_t n = m.nodes.size();
    parent.assign(n, -1);
    for (size_t i = 0; i < n; ++i) {
        const tinygltf::Node& node = m.nodes[i];
        const std::string where = "node " + std::to_string(i);
        for (auto r : {checkRef(where, "mesh", node.mesh, m.meshes.size()), checkRef(where, "skin", node.skin, m.skins.size()),
                       checkRef(where, "camera", node.camera, m.cameras.size()),
                       checkVector(where, "matrix", node.matrix, {0, 16}),
                       checkVector(where, "translation", node.translation, {0, 3}),
                       checkVector(where, "rotation", node.rotation, {0, 4}), checkVector(where, "scale", node.scale, {0, 3})})
            if (!r) return r;
        if (node.rotation.size() == 4 && node.rotation[0] == 0 && node.rotation[1] == 0 && node.rotation[2] == 0 &&
            node.rotation[3] == 0)
            return invalid(where + ": rotation is the zero quaternion");
        for (int child : node.children) {
            if (size_t(child) == i) return invalid(where + " lists itself as a child (a cycle)");
            if (auto r = checkRef(where + " children", "node", child, n, false); !r) return r;
            if (parent[size_t(child)] != -1)
                return invalid("node " + std::to_string(child) + " has two parents (node " +
                               std::to_string(parent[size_t(child)]) + " and node " + std::to_string(i) + ")");
            parent[size_t(child)] = int(i);
        }
    }
    // With one parent per node, a cycle is a closed chain of parents. Walk up from every node,
    // stopping at nodes already known to reach a root, so the whole check is linear (a deep
    // chain of nodes must not make loading quadratic).
    enum : uint8_t { kUnseen, kOnWalk, kReachesRoot };
    std::vector<uint8_t> state(n, kUnseen);
    std::vector<int> walk;
    for (size_t i = 0; i < n; ++i) {
        walk.clear();
        int j = int(i);
        for (; j != -1 && state[size_t(j)] == kUnseen; j = parent[size_t(j)]) {
            state[size_t(j)] = kOnWalk;
            walk.push_back(j);
        }
        if (j != -1 && state[size_t(j)] == kOnWalk) {
            std::vector<int> chain{j};
            for (int k = parent[size_t(j)]; k != j; k = parent[size_t(k)]) chain.push_back(k);
            chain.push_back(j);
            std::string text;
            for (auto it = chain.rbegin(); it != chain.rend(); ++it) text += (text.empty() ? "node " : " -> node ") + std::to_string(*it);
            return invalid("cycle in the node hierarchy: " + text);
        }
        for (int w : walk) state[size_t(w)] = kReachesRoot;
    }
    return {};
}

Result<void> checkScenes(const tinygltf::Model& m, const std::vector<int>& parent) {
    if (auto r = checkRef("the default scene", "scene", m.defaultScene, m.scenes.size()); !r) return r;
    for (size_t s = 0; s < m.scenes.size(); ++s) {
        const std::string where = "scene " + std::to_string(s);
        std::set<int> seen;
        for (int node : m.scenes[s].nodes) {
            if (auto r = checkRef(where, "node", node, m.nodes.size(), false); !r) return r;
            if (!seen.insert(node).second) return invalid(where + " lists node " + std::to_string(node) + " twice");
            if (parent[size_t(node)] != -1)
                return invalid(where + " lists node " + std::to_string(node) + ", a child of node " +
                               std::to_string(parent[size_t(node)]) + " (scene nodes must be roots)");
        }
    }
    return {};
}

Result<void> checkSkins(const tinygltf::Model& m) {
    for (size_t s = 0; s < m.skins.size(); ++s) {
        const tinygltf::Skin& skin = m.skins[s];
        const std::string where = "skin " + std::to_string(s);
        if (skin.joints.empty()) return invalid(where + " has no joints");
        std::set<int> seen;
        for (int joint : skin.joints) {
            if (auto r = checkRef(where + " joints", "node", joint, m.nodes.size(), false); !r) return r;
            if (!seen.insert(joint).second) return invalid(where + " lists joint node " + std::to_string(joint) + " twice");
        }
        if (auto r = checkRef(where + " skeleton", "node", skin.skeleton, m.nodes.size()); !r) return r;
    }
    return {};
}

Result<void> checkAnimations(const tinygltf::Model& m) {
    for (size_t a = 0; a < m.animations.size(); ++a) {
        const tinygltf::Animation& anim = m.animations[a];
        const std::string where = "animation " + std::to_string(a);
        for (size_t c = 0; c < anim.channels.size(); ++c) {
            const tinygltf::AnimationChannel& ch = anim.channels[c];
            const std::string at = where + " channel " + std::to_string(c);
            if (auto r = checkRef(at, "sampler", ch.sampler, anim.samplers.size(), false); !r) return r;
            if (auto r = checkRef(at + " target", "node", ch.target_node, m.nodes.size()); !r) return r;
            const std::string& path = ch.target_path;
            if (path != "translation" && path != "rotation" && path != "scale" && path != "weights")
                return invalid(at + ": target path '" + path + "' is not translation, rotation, scale or weights");
            if (ch.target_node >= 0 && path != "weights" && !m.nodes[size_t(ch.target_node)].matrix.empty())
                return invalid(at + ": animates node " + std::to_string(ch.target_node) +
                               ", which has a matrix (glTF requires TRS on animated nodes)");
        }
        for (size_t s = 0; s < anim.samplers.size(); ++s) {
            const std::string& interpolation = anim.samplers[s].interpolation;
            if (interpolation != "LINEAR" && interpolation != "STEP" && interpolation != "CUBICSPLINE")
                return invalid(where + " sampler " + std::to_string(s) + ": interpolation '" + interpolation +
                               "' is not LINEAR, STEP or CUBICSPLINE");
        }
    }
    return {};
}

} // namespace

std::vector<std::string> accessorUses(const tinygltf::Model& m) {
    std::vector<std::string> uses(m.accessors.size());
    auto use = [&](int index, const std::string& what) {
        if (inRange(index, uses.size()) && uses[size_t(index)].empty()) uses[size_t(index)] = what;
    };
    for (size_t i = 0; i < m.meshes.size(); ++i)
        for (size_t p = 0; p < m.meshes[i].primitives.size(); ++p) {
            const auto& prim = m.meshes[i].primitives[p];
            const std::string where = "of mesh " + std::to_string(i) + " primitive " + std::to_string(p);
            for (const auto& [name, accessor] : prim.attributes) use(accessor, name + " " + where);
            use(prim.indices, "indices " + where);
            for (size_t t = 0; t < prim.targets.size(); ++t)
                for (const auto& [name, accessor] : prim.targets[t]) use(accessor, "morph target " + std::to_string(t) + " " + name + " " + where);
        }
    for (size_t s = 0; s < m.skins.size(); ++s) use(m.skins[s].inverseBindMatrices, "inverseBindMatrices of skin " + std::to_string(s));
    for (size_t a = 0; a < m.animations.size(); ++a)
        for (size_t s = 0; s < m.animations[a].samplers.size(); ++s) {
            const std::string where = "of animation " + std::to_string(a) + " sampler " + std::to_string(s);
            use(m.animations[a].samplers[s].input, "input " + where);
            use(m.animations[a].samplers[s].output, "output " + where);
        }
    return uses;
}

Result<void> validateModel(const tinygltf::Model& m) {
    const auto uses = accessorUses(m);
    for (size_t i = 0; i < m.accessors.size(); ++i)
        if (auto view = viewAccessor(m, int(i), uses[i], 0, {}, true); !view) return view.error();
    std::vector<int> parent;
    for (auto step : {checkMeshes, checkMaterials, checkCameras})
        if (auto r = step(m); !r) return r;
    if (auto r = checkNodes(m, parent); !r) return r;
    if (auto r = checkScenes(m, parent); !r) return r;
    if (auto r = checkSkins(m); !r) return r;
    return checkAnimations(m);
}

} // namespace rrc::scene::detail
