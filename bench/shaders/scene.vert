#version 450 core
// A plane in front of the camera; the cache-time position for the lookup.
#include <rrc/reproject.vert>
layout(location = 0) in vec2 a_corner;
uniform mat4 u_mvp;
uniform mat4 u_model;
out vec3 v_world;
void main() {
    vec4 local = vec4(a_corner, 0.0, 1.0);
    gl_Position = u_mvp * local;
    v_world = (u_model * local).xyz;
    rrc_reproject(local);
}
