// Sampling patterns shared by the demos that supersample stochastically (PCF shadows, bump-env,
// motion blur, depth of field): Poisson-disk taps in the unit disk and stratified sub-pixel
// offsets. Header-only and deterministic: the same (count, seed) always gives the same pattern,
// so golden frames and tests do not depend on the run.
#pragma once
#include <glm/vec2.hpp>

#include <cmath>
#include <cstdint>
#include <vector>

namespace rrc::demo {

// xorshift-style generator: reproducible across compilers and standard libraries (unlike
// std::uniform_real_distribution), which golden frames need.
class PatternRandom {
public:
    explicit PatternRandom(uint32_t seed) : state_(seed * 2654435761u + 0x9e3779b9u) { if (!state_) state_ = 1; }
    uint32_t next() {
        state_ ^= state_ << 13;
        state_ ^= state_ >> 17;
        state_ ^= state_ << 5;
        return state_;
    }
    float uniform() { return static_cast<float>(next() >> 8) * (1.0f / 16777216.0f); }   // [0, 1)

private:
    uint32_t state_;
};

// `count` points in the unit disk by Mitchell's best-candidate algorithm (each new point is the
// farthest of `candidates` random ones from the points so far): a Poisson-disk-like blue-noise
// pattern whose minimum spacing grows as 1/sqrt(count). Points lie strictly inside the disk.
// candidates = kGrowingCandidates: Mitchell's own rule, 10 x (points so far + 1) candidates
// (better spacing, quadratic cost: for the few dozen lens positions of depth of field).
inline constexpr int kGrowingCandidates = 0;
inline std::vector<glm::vec2> poissonDisk(int count, uint32_t seed, int candidates = 24) {
    PatternRandom random(seed);
    auto candidate = [&] {
        const float r = std::sqrt(random.uniform()), a = 6.28318531f * random.uniform();   // uniform in area
        return glm::vec2(r * std::cos(a), r * std::sin(a)) * 0.999f;
    };
    std::vector<glm::vec2> points;
    points.reserve(count > 0 ? static_cast<size_t>(count) : 0);
    for (int i = 0; i < count; ++i) {
        glm::vec2 best{0.0f};
        float bestDistance = -1.0f;
        const int tries = i == 0 ? 1 : candidates == kGrowingCandidates ? 10 * (i + 1) : candidates;
        for (int c = 0; c < tries; ++c) {
            const glm::vec2 p = candidate();
            float nearest = 1e30f;
            for (const glm::vec2& q : points) {
                const glm::vec2 d = p - q;
                nearest = std::fmin(nearest, d.x * d.x + d.y * d.y);
            }
            if (nearest > bestDistance) { bestDistance = nearest; best = p; }
        }
        points.push_back(best);
    }
    return points;
}

// Smallest distance between two points of a pattern (tests, tuning).
inline float minimumSpacing(const std::vector<glm::vec2>& points) {
    float best = 1e30f;
    for (size_t i = 0; i < points.size(); ++i)
        for (size_t j = i + 1; j < points.size(); ++j) {
            const glm::vec2 d = points[i] - points[j];
            best = std::fmin(best, std::sqrt(d.x * d.x + d.y * d.y));
        }
    return best;
}

} // namespace rrc::demo
