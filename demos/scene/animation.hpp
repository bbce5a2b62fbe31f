// Animation sampling: a clip at a time gives the animated nodes' local translation, rotation and
// scale (LINEAR with quaternion slerp, STEP, CUBICSPLINE Hermite), looping or clamped.
#pragma once
#include "scene.hpp"

#include <span>

namespace rrc::scene {

// Maps a time in seconds into the clip's [start, end]: wrapped when looping, clamped otherwise.
double clipTime(const Animation& clip, double time, bool loop);

// One sampler's value at clip time t: xyz for translation/scale, a unit quaternion (x, y, z, w)
// when `rotation` is set. Before the first key / after the last the end values hold.
glm::dvec4 sampleValue(const AnimationSampler& sampler, double t, bool rotation);

// Writes every channel of `clip` at `time` into `locals` (indexed by node); components no channel
// animates keep their values.
void sampleAnimation(const Animation& clip, double time, bool loop, std::span<Transform> locals);

} // namespace rrc::scene
