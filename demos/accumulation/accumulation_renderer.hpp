// Accumulation rendering with the reprojection cache (chapter sections 6.5.2 and 6.5.3): an output
// frame is the average of N sharp samples (time samples across the shutter, or camera positions on
// the lens). Brute force renders every sample in full. Cached: the first sample is rendered in full
// into the cache; every later one looks up the cache of the sample before it (hit: reuse, miss:
// shade) and becomes the cache of the next.
#pragma once
#include "accumulator.hpp"
#include "character.hpp"

#include "support/draw_list.hpp"

#include <rrc/cache.hpp>

#include <span>

namespace rrc::accumulation {

enum class Variant { Brute, Cached };
const char* variantName(Variant v);

struct SampleView {
    glm::dmat4 view{1.0};
    glm::dmat4 projection{1.0};   // reversed-Z perspective (rrc::perspectiveReversedZ)
};

// What a sample draws. `character` (optional) is posed by the caller's sample callback.
struct SceneRef {
    std::span<const demo::DrawCall> statics;
    const Character* character = nullptr;
    bool characterNeverCached = false;   // its look changes within the shutter: force its misses
    bool moving = true;                  // objects move between samples (FrameDesc::objectsMoved)
};

struct RendererSettings {
    int octaves = 8;                      // DEMO_OCTAVES of the marble
    ControlFlow flow = ControlFlow::OnePass;   // measured fastest on llvmpipe (docs/motion_blur.md)
    bool probe = true;                    // TwoPass: skip an empty miss pass
    bool stats = true;                    // per-pixel outcomes counted (hitRate(), visualize())
    uint32_t refreshPeriod = 4;           // > 0: every 8x8 block is shaded afresh every this many
                                          // samples (round robin): bounds the chain of bilinear
                                          // resamplings, whose blur otherwise grows with N
                                          // (docs/motion_blur.md); 0: reuse until a miss
    Resample resample = Resample::Bilinear;
    glm::vec4 background{0.55f, 0.65f, 0.8f, 1.0f};
    float staticPatternScale = 0.12f, characterPatternScale = 0.4f;
};

// Called before sample i of n is drawn: returns its view and poses the scene for it.
using SampleFn = std::function<SampleView(int i, int n)>;

class AccumulationRenderer {
public:
    Result<void> init(int width, int height, ShaderLibrary& library, const RendererSettings& settings = {});
    // Renders `samples` samples and averages them into result(). With `trackHits` the cached
    // variant waits for each sample's statistics (hitRate() is then their mean over samples 1..N-1).
    void render(Variant variant, const SceneRef& scene, int samples, const SampleFn& sampleAt, bool trackHits = false);

    GLuint result() const { return accumulator_.result(); }
    GLuint lastSample(Variant v) const { return v == Variant::Brute ? bruteColor_.id() : cache_.payload(0); }
    Cache& cache() { return cache_; }
    double hitRate() const { return hitTotal_ > 0 ? hits_ / hitTotal_ : 0.0; }
    const RendererSettings& settings() const { return settings_; }

private:
    struct Programs { Program depth, lookup, miss, shade, brute; };
    const Program& program(const Programs& set, Variant variant, Pass pass) const;
    void drawScene(Variant variant, Pass pass, const SampleView& sample, const SceneRef& scene) const;
    void renderBrute(const SampleView& sample, const SceneRef& scene);
    void renderCached(const SampleView& sample, const SceneRef& scene, bool first);

    int width_ = 0, height_ = 0;
    RendererSettings settings_;
    Cache cache_;
    Programs static_, skinned_;
    Texture bruteColor_, bruteDepth_, permutation_;
    Framebuffer bruteFb_;
    Accumulator accumulator_;
    double hits_ = 0, hitTotal_ = 0;
};

} // namespace rrc::accumulation
