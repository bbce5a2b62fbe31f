// What rrc-bump-env and its benchmark share: the camera orbit around the sphere and the sphere's
// slow spin, functions of the fixed clock so headless runs are deterministic.
#pragma once
#include "../common/camera.hpp"

namespace rrc::bump_env {

// Eye 2.6 sphere radii from the centre, slightly above the equator, one turn in 40 s.
inline demo::OrbitPath cameraOrbit() { return {.center = {0.0, 0.0, 0.0}, .radius = 2.6, .height = 0.5, .period = 40.0}; }

} // namespace rrc::bump_env
