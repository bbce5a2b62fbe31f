// Vertex side of the cache lookup: besides its own gl_Position, every vertex outputs its
// cache-time clip position; interpolation gives each fragment the exact cache-time position of
// its surface point, and the fragment shader divides once (rrc/lookup.frag).
#ifndef RRC_REPROJECT_VERT
#define RRC_REPROJECT_VERT

// Passes that share depth (prepass + shading, lookup + miss) must rasterise identical depths.
invariant gl_Position;

uniform mat4 rrc_prevMVP;   // cache-time object-to-clip (rrc::Cache::setDrawUniforms)
out vec4 rrc_vCachePos;

// `localPosition` in object space, the same vertex the current gl_Position was computed from.
void rrc_reproject(vec4 localPosition) { rrc_vCachePos = rrc_prevMVP * localPosition; }

// For positions already moved to their cache-time place in object space (e.g. skinned with the
// previous bone matrices).
void rrc_reprojectPrevious(vec4 previousLocalPosition) { rrc_vCachePos = rrc_prevMVP * previousLocalPosition; }

#endif
