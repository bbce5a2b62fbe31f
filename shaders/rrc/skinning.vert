// Linear blend skinning with the current and the cache-time bone matrices, so animated skinned
// meshes reproject to where their surface really was (the chapter's Heroine and Ninja cases).
#ifndef RRC_SKINNING_VERT
#define RRC_SKINNING_VERT
#include <rrc/reproject.vert>

#ifndef RRC_BONES_BINDING
#define RRC_BONES_BINDING 3
#endif
#ifndef RRC_PREV_BONES_BINDING
#define RRC_PREV_BONES_BINDING 4
#endif

layout(std430, binding = RRC_BONES_BINDING) readonly buffer rrc_BonesBlock { mat4 rrc_bones[]; };
layout(std430, binding = RRC_PREV_BONES_BINDING) readonly buffer rrc_PrevBonesBlock { mat4 rrc_prevBones[]; };

mat4 rrc_skinMatrix(uvec4 joints, vec4 weights) {
    return weights.x * rrc_bones[joints.x] + weights.y * rrc_bones[joints.y] +
           weights.z * rrc_bones[joints.z] + weights.w * rrc_bones[joints.w];
}

mat4 rrc_prevSkinMatrix(uvec4 joints, vec4 weights) {
    return weights.x * rrc_prevBones[joints.x] + weights.y * rrc_prevBones[joints.y] +
           weights.z * rrc_prevBones[joints.z] + weights.w * rrc_prevBones[joints.w];
}

// Outputs the cache-time position of a skinned vertex; returns the current skinned position.
vec4 rrc_skinAndReproject(vec4 bindPosition, uvec4 joints, vec4 weights) {
    rrc_reprojectPrevious(rrc_prevSkinMatrix(joints, weights) * bindPosition);
    return rrc_skinMatrix(joints, weights) * bindPosition;
}

#endif
