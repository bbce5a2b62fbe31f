// The stereo demo's expensive shading: 5-octave Perlin marble (support/shaders/perlin.glsl) lit by
// one directional light, split into the view-independent part (ambient + diffuse) and the
// view-dependent Blinn-Phong specular term, so the cached variants can treat them differently.
#ifndef STEREO_SHADE_GLSL
#define STEREO_SHADE_GLSL
#include <support/shaders/perlin.glsl>

in vec3 v_world;
in vec3 v_normal;
uniform vec4 u_baseColor;
uniform vec3 u_eye;          // world-space eye position of the view being rendered
const vec3 kLight = normalize(vec3(0.45, 0.8, 0.35));

vec3 viewIndependent() {
    vec3 n = normalize(v_normal);
    vec3 albedo = demo_marble(v_world * 0.35) * u_baseColor.rgb;
    return albedo * (0.25 + 0.75 * max(dot(n, kLight), 0.0));
}

vec3 specular() {
    vec3 n = normalize(v_normal);
    vec3 h = normalize(kLight + normalize(u_eye - v_world));
    return vec3(0.9) * pow(max(dot(n, h), 0.0), 48.0) * step(0.0, dot(n, kLight));
}

#endif
