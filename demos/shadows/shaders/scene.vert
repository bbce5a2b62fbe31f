#version 450 core
// Scene geometry for every shadow variant: world position and normal for the light-space
// lookup, and the cache-time position for the reprojection (unused by the PCF variants).
#include <rrc/reproject.vert>
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
uniform mat4 u_mvp;
uniform mat4 u_model;
out vec3 v_world;
out vec3 v_normal;
void main() {
    vec4 p = vec4(a_position, 1.0);
    gl_Position = u_mvp * p;
    v_world = (u_model * p).xyz;
    v_normal = mat3(u_model) * a_normal;   // models are rotations, translations, uniform scales
    rrc_reproject(p);
}
