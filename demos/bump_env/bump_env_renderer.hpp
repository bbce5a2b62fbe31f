// Environment-mapped bump mapping supersampled per pixel (chapter section 6.5.4): k = n x n
// sub-pixel samples of the bumped normal -> reflection -> cube-map lookup, brute force or
// amortized through the reprojection cache with the recursive filter.
#pragma once
#include "../common/fullscreen.hpp"
#include "../support/procedural.hpp"

#include <rrc/cache.hpp>

#include <string>

namespace rrc::bump_env {

enum class Variant { Brute, Amortized };
const char* variantName(Variant v);   // "brute", "amortized"

struct BumpSettings {
    int grid = 2;                 // n: k = n * n samples per pixel and frame (1..16)
    float lambda = 0.6f;          // recursive filter weight (amortized)
    bool jitter = true;           // false: stratum centres, the same every frame (the reference)
    float bumpStrength = 6.0f;
    uint32_t seed = 1;
};

struct BumpFrame {
    glm::dmat4 view{1.0}, projection{1.0};      // reversed-Z camera
    glm::dmat4 model{1.0}, prevModel{1.0};      // the sphere now / last frame
    uint32_t frame = 0;
};

class BumpEnvRenderer {
public:
    // Loads <assetDir>/bump.png and <assetDir>/env/{px,nx,py,ny,pz,nz}.png.
    // `age` / `stats`: the cache's optional targets (see shadows::CacheFeatures).
    Result<void> init(int width, int height, const ShaderLibrary& library, const std::string& assetDir = "assets",
                      bool age = true, bool stats = true);
    void render(Variant variant, const BumpSettings& settings, const BumpFrame& frame);

    GLuint color() const;   // RGBA16F: the last render (sphere and sky) of the last variant rendered
    Cache& cache() { return cache_; }
    GLuint environment() const { return environment_.id(); }

private:
    void drawSphere(GLuint program, const BumpSettings& settings, const BumpFrame& frame, bool withCache) const;
    void drawSky(const BumpFrame& frame, int attachments);

    int width_ = 0, height_ = 0;
    Cache cache_;
    Program brute_, amortized_;
    demo::FullscreenPass sky_;
    Variant lastVariant_ = Variant::Brute;
    demo::MeshBuffers sphere_;
    Texture slopes_, environment_, bruteColor_, bruteDepth_;
    Framebuffer bruteFb_;
};

// A unit UV sphere (attributes 0 position, 1 normal), `slices` x `stacks` quads.
demo::MeshBuffers makeSphere(int slices, int stacks);

// Height slopes of a grey bump map (central differences, wrapping) as an RG32F texture, REPEAT.
Result<Texture> loadBumpSlopes(const std::string& path);
// Six faces <dir>/{px,nx,py,ny,pz,nz}.png as an RGBA8 cube map (no flip, see assets/env/README.md).
Result<Texture> loadCubeMap(const std::string& dir);

} // namespace rrc::bump_env
