// Mesh primitives: vertex attributes to float vectors (normalized integers converted), indices to
// uint32 (checked against the vertex count), joints to u16vec4 (checked against skins later).
#include "gltf_accessor.hpp"
#include "gltf_convert.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <optional>

namespace rrc::scene::detail {
namespace {

constexpr Format kFloat{TINYGLTF_COMPONENT_TYPE_FLOAT, false};
constexpr Format kUByteNorm{TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, true};
constexpr Format kUShortNorm{TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, true};
constexpr Format kUByte{TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, false};
constexpr Format kUShort{TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, false};
constexpr Format kUInt{TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, false};

struct Attribute {
    const tinygltf::Model& model;
    const tinygltf::Primitive& primitive;
    const std::string& where;   // "mesh 0 primitive 1"
    LoadContext& context;

    int accessor(const char* name) const {
        const auto it = primitive.attributes.find(name);
        return it == primitive.attributes.end() ? -1 : it->second;
    }

    // Reads attribute `name` (absent: out stays empty) as N floats per vertex.
    template <int N, class T>
    Result<void> read(const char* name, int type, std::initializer_list<Format> formats, std::optional<size_t> vertexCount,
                      std::vector<T>& out) const {
        const int index = accessor(name);
        if (index < 0) return {};
        const std::string use = std::string(name) + " of " + where;
        auto view = viewAccessor(model, index, use, type, formats);
        if (!view) return view.error();
        const AccessorView& v = view.value();
        const std::string what = describeAccessor(index, use);
        if (vertexCount && v.count != *vertexCount)
            return invalid(what + ": count " + std::to_string(v.count) + " differs from the POSITION count " + std::to_string(*vertexCount));
        if (!context.charge(uint64_t(v.count) * sizeof(T), what)) return invalid(context.budgetError);
        out.resize(v.count);
        for (size_t i = 0; i < v.count; ++i)
            for (int c = 0; c < N; ++c) {
                const double value = v.get(i, c);
                if constexpr (std::is_floating_point_v<typename T::value_type>) {
                    if (!std::isfinite(float(value)))
                        return invalid(what + ": vertex " + std::to_string(i) + " component " + std::to_string(c) +
                                       " is not finite (" + std::to_string(value) + ")");
                }
                out[i][c] = typename T::value_type(value);
            }
        return {};
    }
};

Result<void> readIndices(const tinygltf::Model& model, const tinygltf::Primitive& prim, const std::string& where,
                         size_t vertexCount, LoadContext& context, std::vector<uint32_t>& out) {
    if (prim.indices < 0) {
        if (vertexCount % 3 != 0)
            return invalid(where + ": " + std::to_string(vertexCount) + " vertices without indices are not whole triangles");
        if (!context.charge(uint64_t(vertexCount) * 4, where + " generated indices")) return invalid(context.budgetError);
        out.resize(vertexCount);
        std::iota(out.begin(), out.end(), 0u);
        return {};
    }
    const std::string use = "indices of " + where;
    auto view = viewAccessor(model, prim.indices, use, TINYGLTF_TYPE_SCALAR, {kUByte, kUShort, kUInt});
    if (!view) return view.error();
    const AccessorView& v = view.value();
    const std::string what = describeAccessor(prim.indices, use);
    if (v.count % 3 != 0) return invalid(what + ": count " + std::to_string(v.count) + " is not a multiple of 3 (triangles)");
    if (!context.charge(uint64_t(v.count) * 4, what)) return invalid(context.budgetError);
    out.resize(v.count);
    for (size_t i = 0; i < v.count; ++i) {
        out[i] = v.getUint(i, 0);
        if (out[i] >= vertexCount)
            return invalid(what + ": index " + std::to_string(out[i]) + " (element " + std::to_string(i) + ") >= vertex count " +
                           std::to_string(vertexCount));
    }
    return {};
}

Result<void> convertPrimitive(const tinygltf::Model& model, const tinygltf::Primitive& prim, const std::string& where,
                              LoadContext& context, Primitive& out) {
    const Attribute attribute{model, prim, where, context};
    if (auto r = attribute.read<3>("POSITION", TINYGLTF_TYPE_VEC3, {kFloat}, std::nullopt, out.positions); !r) return r;
    const size_t n = out.positions.size();
    for (auto r : {attribute.read<3>("NORMAL", TINYGLTF_TYPE_VEC3, {kFloat}, n, out.normals),
                   attribute.read<2>("TEXCOORD_0", TINYGLTF_TYPE_VEC2, {kFloat, kUByteNorm, kUShortNorm}, n, out.uv0),
                   attribute.read<4>("TANGENT", TINYGLTF_TYPE_VEC4, {kFloat}, n, out.tangents),
                   attribute.read<4>("JOINTS_0", TINYGLTF_TYPE_VEC4, {kUByte, kUShort}, n, out.joints),
                   attribute.read<4>("WEIGHTS_0", TINYGLTF_TYPE_VEC4, {kFloat, kUByteNorm, kUShortNorm}, n, out.weights)})
        if (!r) return r;
    if (out.joints.empty() != out.weights.empty())
        return invalid(where + ": JOINTS_0 and WEIGHTS_0 must come together");
    if (auto r = readIndices(model, prim, where, n, context, out.indices); !r) return r;
    out.material = prim.material;
    out.boundsMin = out.boundsMax = out.positions.front();
    for (const glm::vec3& p : out.positions) {
        out.boundsMin = glm::min(out.boundsMin, p);
        out.boundsMax = glm::max(out.boundsMax, p);
    }
    return {};
}

} // namespace

Result<void> convertMeshes(const tinygltf::Model& model, Scene& scene, LoadContext& context) {
    scene.meshes.resize(model.meshes.size());
    for (size_t m = 0; m < model.meshes.size(); ++m) {
        Mesh& mesh = scene.meshes[m];
        mesh.name = model.meshes[m].name;
        mesh.primitives.resize(model.meshes[m].primitives.size());
        for (size_t p = 0; p < mesh.primitives.size(); ++p) {
            const std::string where = "mesh " + std::to_string(m) + " primitive " + std::to_string(p);
            if (auto r = convertPrimitive(model, model.meshes[m].primitives[p], where, context, mesh.primitives[p]); !r) return r;
        }
    }
    return {};
}

Result<void> checkSkinnedMeshes(const Scene& scene) {
    // The largest joint index per mesh once, then one comparison per skinned node: many nodes
    // sharing a big mesh must not multiply the work.
    std::vector<int> maxJoint(scene.meshes.size(), -1);
    for (size_t m = 0; m < scene.meshes.size(); ++m)
        for (const Primitive& p : scene.meshes[m].primitives)
            for (const glm::u16vec4& j : p.joints)
                maxJoint[m] = std::max({maxJoint[m], int(j.x), int(j.y), int(j.z), int(j.w)});
    for (size_t i = 0; i < scene.nodes.size(); ++i) {
        const Node& node = scene.nodes[i];
        if (node.mesh < 0 || node.skin < 0) continue;
        const size_t joints = scene.skins[size_t(node.skin)].joints.size();
        if (maxJoint[size_t(node.mesh)] >= int(joints))
            return invalid("node " + std::to_string(i) + " (skin " + std::to_string(node.skin) + ", " + std::to_string(joints) +
                           " joints): its mesh " + std::to_string(node.mesh) + " uses joint " +
                           std::to_string(maxJoint[size_t(node.mesh)]) + " (JOINTS_0)");
    }
    return {};
}

} // namespace rrc::scene::detail
