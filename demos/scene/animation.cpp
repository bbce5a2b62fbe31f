// Keyframe interpolation per glTF 2.0 Appendix C (interpolation): key search by binary search,
// slerp along the shorter arc for LINEAR rotations, Hermite splines scaled by the key interval.
#include "animation.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace rrc::scene {
namespace {

glm::dquat toQuat(const glm::dvec4& v) { return glm::dquat(v.w, v.x, v.y, v.z); }
glm::dvec4 toVec(const glm::dquat& q) { return glm::dvec4(q.x, q.y, q.z, q.w); }

glm::dvec4 normalizedRotation(const glm::dvec4& v, const glm::dvec4& fallback) {
    const double length = glm::length(v);
    return length > 1e-12 ? v / length : fallback;
}

} // namespace

double clipTime(const Animation& clip, double time, bool loop) {
    const double length = clip.end - clip.start;
    if (!std::isfinite(time) || !(length > 0.0)) return clip.start;
    if (!loop) return std::clamp(time, clip.start, clip.end);
    double t = std::fmod(time - clip.start, length);
    if (t < 0.0) t += length;
    return clip.start + t;
}

glm::dvec4 sampleValue(const AnimationSampler& sampler, double t, bool rotation) {
    const auto& times = sampler.times;
    assert(!times.empty());
    const bool cubic = sampler.interpolation == Interpolation::CubicSpline;
    auto key = [&](size_t k) { return cubic ? sampler.values[3 * k + 1] : sampler.values[k]; };
    auto finish = [&](const glm::dvec4& v) { return rotation ? normalizedRotation(v, glm::dvec4(0, 0, 0, 1)) : v; };
    if (!(t > times.front())) return finish(key(0));
    if (t >= times.back()) return finish(key(times.size() - 1));

    // times[k] <= t < times[k + 1], so the interval is never empty.
    const size_t k = size_t(std::upper_bound(times.begin(), times.end(), t) - times.begin()) - 1;
    const double dt = times[k + 1] - times[k];
    const double u = (t - times[k]) / dt;
    switch (sampler.interpolation) {
    case Interpolation::Step:
        return finish(key(k));
    case Interpolation::Linear:
        if (rotation) return toVec(glm::slerp(glm::normalize(toQuat(key(k))), glm::normalize(toQuat(key(k + 1))), u));
        return glm::mix(key(k), key(k + 1), u);
    case Interpolation::CubicSpline: {
        const glm::dvec4 p0 = key(k), p1 = key(k + 1);
        const glm::dvec4 m0 = dt * sampler.values[3 * k + 2];        // out-tangent of key k
        const glm::dvec4 m1 = dt * sampler.values[3 * (k + 1)];      // in-tangent of key k + 1
        const double u2 = u * u, u3 = u2 * u;
        const glm::dvec4 v = (2 * u3 - 3 * u2 + 1) * p0 + (u3 - 2 * u2 + u) * m0 + (-2 * u3 + 3 * u2) * p1 + (u3 - u2) * m1;
        return rotation ? normalizedRotation(v, normalizedRotation(p0, glm::dvec4(0, 0, 0, 1))) : v;
    }
    }
    return key(k);
}

void sampleAnimation(const Animation& clip, double time, bool loop, std::span<Transform> locals) {
    const double t = clipTime(clip, time, loop);
    for (const AnimationChannel& channel : clip.channels) {
        assert(channel.node < locals.size() && channel.sampler < clip.samplers.size());
        Transform& local = locals[channel.node];
        const bool rotation = channel.path == AnimationPath::Rotation;
        const glm::dvec4 v = sampleValue(clip.samplers[channel.sampler], t, rotation);
        switch (channel.path) {
        case AnimationPath::Translation: local.translation = glm::dvec3(v); break;
        case AnimationPath::Rotation: local.rotation = toQuat(v); break;
        case AnimationPath::Scale: local.scale = glm::dvec3(v); break;
        }
    }
}

} // namespace rrc::scene
