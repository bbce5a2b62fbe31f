#version 450 core
// The bump-mapped sphere: object-space position for the per-sample surface reconstruction, and
// the cache-time position for the reprojection (unused by the brute-force variants).
#include <rrc/reproject.vert>
layout(location = 0) in vec3 a_position;
uniform mat4 u_mvp;
out vec3 v_object;
void main() {
    vec4 p = vec4(a_position, 1.0);
    gl_Position = u_mvp * p;
    v_object = a_position;
    rrc_reproject(p);
}
