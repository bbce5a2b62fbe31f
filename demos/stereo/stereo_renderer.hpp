// Anaglyph stereo with the reprojection cache (chapter section 6.5.1): the right eye is rendered
// fully into the cache, the left eye looks each pixel up (hit: reuse, miss: shade), and the two
// are composited (red from the left eye, green/blue from the right). Brute force shades both.
#pragma once
#include "../support/draw_list.hpp"

#include <rrc/cache.hpp>

namespace rrc::stereo {

enum class Variant { Brute, Cached, CachedViewDependent };
const char* variantName(Variant v);

struct EyeViews {
    glm::dmat4 left, right;     // view matrices
    glm::dvec3 leftEye, rightEye;
    glm::dmat4 projection;      // reversed-Z, shared by both eyes
};

// Two eyes `separation` apart along the camera's right axis, parallel view directions.
EyeViews eyeViews(const glm::dmat4& centerView, const glm::dmat4& projection, double separation);

class StereoRenderer {
public:
    Result<void> init(int width, int height, ShaderLibrary& library, int octaves = 5);
    // The cached variants' control flow (default OnePass; `probe`: TwoPass skips an empty miss
    // pass). Call before init(): the caches of a one-pass flow need no stencil (CacheDesc::stencil).
    void setFlow(ControlFlow flow, bool probe) { flow_ = flow; probe_ = probe; }
    void render(Variant variant, const EyeViews& eyes, std::span<const demo::DrawCall> scene);
    // Cached variants: the left eye once more over a cache holding that same left eye (every
    // pixel hits): what the lookup alone costs.
    void renderLeftAgain(Variant variant, const EyeViews& eyes, std::span<const demo::DrawCall> scene);

    GLuint anaglyph() const { return anaglyph_.id(); }
    GLuint leftEye(Variant v) const;
    GLuint rightEye(Variant v) const;
    GLuint specularMask() const { return bruteSpecular_.id(); }   // brute only
    Cache& cache(Variant v) { return v == Variant::CachedViewDependent ? cacheVD_ : cache_; }

private:
    struct Programs { Program lookup, miss, shade, depthOnly; };
    void drawScene(const Program& program, const glm::dmat4& view, const glm::dmat4& projection, glm::dvec3 eye,
                   const Cache* cache, std::span<const demo::DrawCall> scene) const;
    void composite(GLuint left, GLuint right);
    void renderEye(Variant variant, const glm::dmat4& view, const glm::dmat4& projection, glm::dvec3 position,
                   std::span<const demo::DrawCall> scene);

    int width_ = 0, height_ = 0;
    ControlFlow flow_ = ControlFlow::OnePass;   // measured fastest on llvmpipe (docs/stereo.md)
    bool probe_ = true;
    Cache cache_, cacheVD_;
    Programs cached_, cachedVD_;
    Program brute_, composite_;
    Texture bruteLeft_, bruteRight_, bruteDepth_, bruteSpecular_, anaglyph_, permutation_;
    Framebuffer bruteLeftFb_, bruteRightFb_, anaglyphFb_;
    VertexArray emptyVao_;
};

} // namespace rrc::stereo
