// Motion blur by accumulation (chapter section 6.5.2): the skinned character runs down the
// procedural colonnade while the camera tracks it, and each output frame integrates N time samples across
// the shutter interval.
#pragma once
#include <glm/mat4x4.hpp>

namespace rrc::motion_blur {

struct Shot {
    double shutter = 1.0 / 30.0;   // seconds the shutter stays open (a 360-degree shutter at 30 Hz)
    double speed = 4.0;            // the character's running speed, m/s
};

// Time of sample i of n in the frame that opens at `frameTime`: the midpoints of n equal strata.
double sampleTime(const Shot& shot, double frameTime, int i, int n);
// Where the character (its "heroine" node) is at time t: on the colonnade's stylobate, running
// towards -z.
glm::dmat4 characterPlacement(const Shot& shot, double t);
// The tracking camera at time t: behind and to the left of the runner, swaying sideways.
glm::dmat4 cameraView(const Shot& shot, double t);

} // namespace rrc::motion_blur
