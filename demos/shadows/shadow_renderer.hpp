// Shadow-map PCF with k rotated Poisson taps (chapter section 6.5.5), plain or amortized through
// the reprojection cache with the recursive filter, plus the fig. 6.9 options (depth-aware blur
// of the cached visibility, smoothstep remap, threshold). The shadow map is updated only when
// the light or the caster moved, and the static scene's depth is re-rendered only when the light
// moved (a moving caster costs a copy of it plus the caster's own triangles).
#pragma once
#include "../common/fullscreen.hpp"
#include "../support/draw_list.hpp"
#include "../support/procedural.hpp"

#include <rrc/cache.hpp>

#include <glm/vec3.hpp>

#include <span>

namespace rrc::shadows {

enum class Variant { Pcf, Amortized };
const char* variantName(Variant v);   // "pcf", "amortized"

// How the amortized variant runs through rrc::Cache (docs/shadows.md has the measurements).
enum class Flow {
    SinglePass,   // TwoPass without prepass whose lookup pass shades every pixel (the miss pass
                  // then has nothing to do): lookup + blend folded into the one shading pass
    OnePass,      // ControlFlow::OnePass: depth prepass, then the branching shading pass
    TwoPass,      // ControlFlow::TwoPass: hits blend in the lookup pass, misses in the miss pass
};
const char* flowName(Flow f);

enum class Remap { None = 0, Smoothstep = 1, Threshold = 2 };

struct ShadowSettings {
    int taps = 4;                 // k, 1..256
    float lambda = 0.75f;         // recursive filter weight (amortized): the lowest RMSE on the
                                  // moving sequence of rrc-bench (docs/shadows.md)
    bool blur = false;            // depth-aware 5x5 blur of the visibility (fed back into the cache)
    Remap remap = Remap::None;
    float radius = 0.25f;         // PCF filter radius, metres on the light's image plane
    Flow flow = Flow::OnePass;    // measured fastest on the temple (docs/shadows.md)
    uint32_t seed = 1;            // with the frame number: the per-pixel tap rotation
};

struct ShadowFrame {
    glm::dmat4 view{1.0}, projection{1.0};   // reversed-Z camera
    glm::dvec3 toLight{0.0, 1.0, 0.0};       // unit vector towards the directional light
    glm::dmat4 caster{1.0}, prevCaster{1.0}; // the moving caster's model matrix now / last frame
    uint32_t frame = 0;
};

// Optional cache targets: the age target makes the filter a running mean while an entry is young
// (faster convergence after misses), the stats target counts hits; each costs a fetch or a write.
struct CacheFeatures {
    bool age = true;
    bool stats = true;
    bool bilinear = true;   // false: nearest cached depth and visibility (plain texel fetches);
                            // visibility is smooth across a pixel, so little is lost
    bool depthInPayload = true;   // visibility and linear depth in one RG32F payload: the lookup's
                                  // depth test and the blend share a single fetch
    bool stencil = false;         // CacheDesc::stencil: only Flow::TwoPass needs it (the
                                  // cache refuses that flow without); off saves 1-2 ms a frame
    float resampleSnap = 0.0f;    // CacheDesc::resampleSnap: off, since 32-bit float stores are
                                  // exact (the snap guards against float16 truncation drift under
                                  // a static view) and it costs ~1 ms per 1024x768 frame
};

class ShadowRenderer {
public:
    // `scene`: static receivers and casters; their bounds fit the light's frustum.
    Result<void> init(int width, int height, const ShaderLibrary& library, std::span<const demo::DrawCall> scene,
                      glm::dvec3 boundsMin, glm::dvec3 boundsMax, int shadowMapSize = 2048, CacheFeatures features = {});
    void render(Variant variant, const ShadowSettings& settings, const ShadowFrame& frame);

    GLuint color(Variant v) const;        // final colour of the last render of `v`
    GLuint visibility(Variant v) const;   // visibility it was shaded with (after blur)
    Cache& cache() { return cache_; }
    static constexpr GLuint kShadowUnitBinding = 4;   // pcf.glsl binding of shadow_map
    int shadowMapRenders() const { return shadowMapRenders_; }         // updates of the map (caster or light moved)
    int staticShadowRenders() const { return staticRenders_; }         // of the static scene's depth (light moved)
    void invalidateShadowMap() { shadowMapValid_ = false; }   // benchmarks: every variant pays its own update
    GLuint shadowMap() const { return shadowMap_.id(); }
    glm::dmat4 lightMatrix() const { return lightMatrix_; }

private:
    struct Target { Texture visibility, color, depth; Framebuffer fb; };
    void updateShadowMap(const ShadowFrame& frame);
    void drawDepth(const glm::dmat4& model, GLuint vertexArray, GLsizei count, GLenum type) const;
    void drawScene(GLuint program, const ShadowFrame& frame, const ShadowSettings& settings, bool withCache) const;
    void postProcess(Variant variant, const ShadowSettings& settings, GLuint visibility, GLuint albedo, GLuint depth);
    const Program& shadeProgram(Variant v, bool deferred, bool lookupPass) const;

    int width_ = 0, height_ = 0, shadowMapSize_ = 0;
    std::vector<demo::DrawCall> scene_;
    demo::MeshBuffers casterMesh_;
    glm::dvec3 center_{0.0};
    double radius_ = 1.0;
    glm::dmat4 lightView_{1.0}, lightProjection_{1.0}, lightMatrix_{1.0};
    glm::dvec3 lastToLight_{0.0};
    glm::dmat4 lastCaster_{0.0};
    bool shadowMapValid_ = false, staticValid_ = false;
    int shadowMapRenders_ = 0, staticRenders_ = 0;
    Cache cache_;
    Program shade_[2][2][2];   // [amortized][deferred][lookup pass]
    Program lightDepth_, depthOnly_;
    demo::FullscreenPass blur_, composite_;
    Texture shadowMap_, staticDepth_, blurred_;
    Framebuffer shadowFb_, staticFb_, blurFb_, compositeFb_[2];
    Texture composited_[2];
    Target pcf_;
    bool post_[2] = {false, false};
    GLuint lastVisibility_[2] = {0, 0};
    std::vector<float> disk_;   // 256 taps, x y interleaved
};

// A 1 x 1.6 x 1 box standing on y = 0 (attributes 0 and 1): the moving caster.
demo::MeshBuffers makeCasterBox();

} // namespace rrc::shadows
