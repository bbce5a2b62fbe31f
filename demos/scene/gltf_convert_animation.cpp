// Animation clips: key times (finite, non-decreasing) and values per sampler, typed by the
// channel that uses the sampler. Morph-target "weights" channels are dropped (no morph support).
#include "gltf_accessor.hpp"
#include "gltf_convert.hpp"

#include <algorithm>
#include <cmath>

namespace rrc::scene::detail {
namespace {

constexpr Format kFloat{TINYGLTF_COMPONENT_TYPE_FLOAT, false};

Interpolation interpolation(const std::string& name) {
    return name == "STEP" ? Interpolation::Step : name == "CUBICSPLINE" ? Interpolation::CubicSpline : Interpolation::Linear;
}

Result<void> convertSampler(const tinygltf::Model& model, const tinygltf::AnimationSampler& in, AnimationPath path,
                            const std::string& where, LoadContext& context, AnimationSampler& out) {
    out.interpolation = interpolation(in.interpolation);
    auto times = viewAccessor(model, in.input, "input of " + where, TINYGLTF_TYPE_SCALAR, {kFloat});
    if (!times) return times.error();
    const std::string timesName = describeAccessor(in.input, "input of " + where);
    const bool rotation = path == AnimationPath::Rotation;
    // glTF allows normalized integer rotations (KHR_mesh_quantization made them common).
    auto values = rotation ? viewAccessor(model, in.output, "output of " + where, TINYGLTF_TYPE_VEC4,
                                          {kFloat, {TINYGLTF_COMPONENT_TYPE_BYTE, true}, {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, true},
                                           {TINYGLTF_COMPONENT_TYPE_SHORT, true}, {TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, true}})
                           : viewAccessor(model, in.output, "output of " + where, TINYGLTF_TYPE_VEC3, {kFloat});
    if (!values) return values.error();
    const std::string valuesName = describeAccessor(in.output, "output of " + where);

    const size_t keys = times.value().count;
    const size_t perKey = out.interpolation == Interpolation::CubicSpline ? 3 : 1;
    if (values.value().count != keys * perKey)
        return invalid(valuesName + ": count " + std::to_string(values.value().count) + ", expected " + std::to_string(keys * perKey) +
                       " for " + std::to_string(keys) + " keys" + (perKey == 3 ? " (CUBICSPLINE: 3 per key)" : ""));
    if (!context.charge(uint64_t(keys) * sizeof(double) + uint64_t(keys) * perKey * sizeof(glm::dvec4), where))
        return invalid(context.budgetError);
    out.times.resize(keys);
    for (size_t k = 0; k < keys; ++k) {
        out.times[k] = times.value().get(k, 0);
        if (!std::isfinite(out.times[k])) return invalid(timesName + ": key " + std::to_string(k) + " time is not finite");
        if (k > 0 && out.times[k] < out.times[k - 1])
            return invalid(timesName + ": key " + std::to_string(k) + " time " + std::to_string(out.times[k]) +
                           " is before the previous key's " + std::to_string(out.times[k - 1]));
    }
    const int components = rotation ? 4 : 3;
    out.values.assign(values.value().count, glm::dvec4(0.0));
    for (size_t i = 0; i < out.values.size(); ++i)
        for (int c = 0; c < components; ++c) {
            out.values[i][c] = values.value().get(i, c);
            if (!std::isfinite(out.values[i][c])) return invalid(valuesName + ": value " + std::to_string(i) + " is not finite");
        }
    // Key rotations are normalized when sampled; a zero quaternion has no direction to normalize to.
    for (size_t i = rotation ? perKey / 2 : out.values.size(); i < out.values.size(); i += perKey)
        if (out.values[i] == glm::dvec4(0.0)) return invalid(valuesName + ": key " + std::to_string(i / perKey) + " is the zero quaternion");
    return {};
}

AnimationPath pathOf(const std::string& name) {
    return name == "rotation" ? AnimationPath::Rotation : name == "scale" ? AnimationPath::Scale : AnimationPath::Translation;
}

} // namespace

Result<void> convertAnimations(const tinygltf::Model& model, Scene& scene, LoadContext& context) {
    for (size_t a = 0; a < model.animations.size(); ++a) {
        const tinygltf::Animation& in = model.animations[a];
        Animation clip{.name = in.name};
        clip.samplers.resize(in.samplers.size());
        std::vector<int> samplerPath(in.samplers.size(), -1);  // which value type each sampler was read as
        bool anyKeys = false;
        for (const tinygltf::AnimationChannel& ch : in.channels) {
            if (ch.target_path == "weights" || ch.target_node < 0) continue;
            const AnimationPath path = pathOf(ch.target_path);
            const size_t s = size_t(ch.sampler);
            const std::string where = "animation " + std::to_string(a) + " sampler " + std::to_string(s);
            const int kind = path == AnimationPath::Rotation ? 1 : 0;  // translation and scale share a value type
            if (samplerPath[s] < 0) {
                if (auto r = convertSampler(model, in.samplers[s], path, where, context, clip.samplers[s]); !r) return r;
                samplerPath[s] = kind;
                const auto& times = clip.samplers[s].times;
                clip.start = anyKeys ? std::min(clip.start, times.front()) : times.front();
                clip.end = anyKeys ? std::max(clip.end, times.back()) : times.back();
                anyKeys = true;
            } else if (samplerPath[s] != kind) {
                return invalid(where + " drives both a rotation and a translation or scale");
            }
            clip.channels.push_back({.sampler = uint32_t(s), .node = uint32_t(ch.target_node), .path = path});
        }
        scene.animations.push_back(std::move(clip));
    }
    return {};
}

} // namespace rrc::scene::detail
