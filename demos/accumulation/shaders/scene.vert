#version 450 core
// Geometry of every pass and variant. SKINNED: linear blend skinning with the current and the
// cache-time bone matrices (rrc/skinning.vert). The marble is fixed to the surface (world position
// for the static scene, bind-pose position for the character), so a surface point keeps its colour
// from sample to sample and the cache may reuse it.
// (The composer inlines each file once, whatever the #if around it: reproject.vert first, outside
// any conditional, so that skinning.vert's own include of it is the skipped one.)
#include <rrc/reproject.vert>
#ifdef SKINNED
#include <rrc/skinning.vert>
#endif
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
#ifdef SKINNED
layout(location = 4) in uvec4 a_joints;
layout(location = 5) in vec4 a_weights;
#endif
uniform mat4 u_mvp;
uniform mat4 u_model;
uniform float u_patternScale;
out vec3 v_pattern;
out vec3 v_normal;

void main() {
    vec4 p = vec4(a_position, 1.0);
#ifdef SKINNED
    vec4 posed = rrc_skinAndReproject(p, a_joints, a_weights);
    gl_Position = u_mvp * posed;
    v_normal = mat3(u_model) * mat3(rrc_skinMatrix(a_joints, a_weights)) * a_normal;
    v_pattern = a_position * u_patternScale;
#else
    gl_Position = u_mvp * p;
    rrc_reproject(p);
    v_normal = mat3(u_model) * a_normal;   // rotations and uniform scales
    v_pattern = (u_model * p).xyz * u_patternScale;
#endif
}
