// Blinn-Phong with the view-independent part (ambient + diffuse) and the view-dependent part
// (specular) returned separately: a stereo or multi-view demo caches the first and adds the
// second after the cache lookup (chapter section 6.5.1).
#ifndef RRC_DEMO_LIGHTING_GLSL
#define RRC_DEMO_LIGHTING_GLSL

struct demo_Shading {
    vec3 viewIndependent;   // albedo * (ambient + light * max(N.L, 0))
    vec3 specular;          // specularColor * light * max(N.H, 0)^shininess, 0 where N.L <= 0
};

struct demo_Light {
    vec3 toLight;           // direction towards the light (need not be normalised)
    vec3 color;
    vec3 ambient;
};

demo_Shading demo_blinnPhong(vec3 albedo, vec3 normal, vec3 toEye, demo_Light light,
                             vec3 specularColor, float shininess) {
    vec3 n = normalize(normal), l = normalize(light.toLight), v = normalize(toEye);
    float ndl = max(dot(n, l), 0.0);
    vec3 h = normalize(l + v);
    float spec = ndl > 0.0 ? pow(max(dot(n, h), 0.0), shininess) : 0.0;
    return demo_Shading(albedo * (light.ambient + light.color * ndl), specularColor * light.color * spec);
}

vec3 demo_total(demo_Shading s) { return s.viewIndependent + s.specular; }

#endif
