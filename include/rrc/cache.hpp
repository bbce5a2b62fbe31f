// The Real-Time Reprojection Cache (Nehab, Sander, Isidoro 2006): screen-space payload targets +
// depth, double-buffered (read the previous render, write the current), the cache-time state the
// lookup needs, control flow between the hit and miss paths, refresh and statistics.
//
//   rrc::Cache cache = rrc::Cache::create({.width = 1024, .height = 768}).value();
//   cache.beginFrame({.view = v, .projection = p});          // swaps: last render becomes the cache
//   cache.render(rrc::ControlFlow::TwoPass, [&](rrc::Pass pass) { drawScene(programs[pass]); });
//   cache.endFrame();                                        // stats of an older frame, no stall
#pragma once
#include <rrc/gl_object.hpp>
#include <rrc/motion.hpp>
#include <rrc/refresh.hpp>
#include <rrc/shader.hpp>

#include <functional>
#include <memory>
#include <vector>

namespace rrc {

enum class Resample : int { Nearest = 0, Bilinear = 1, Bicubic = 2 };

struct PayloadDesc {
    GLenum format = GL_RGBA16F;           // GL_RGBA8, GL_RGBA16F, GL_RGBA32F, GL_R32F, GL_RG16F,
                                          // GL_R32UI (integer formats resample Nearest only)
    Resample resample = Resample::Bilinear;
};

// Defaults are listed with each field; width and height are required.
struct CacheDesc {
    int width = 0;
    int height = 0;
    std::vector<PayloadDesc> payloads = {PayloadDesc{}};  // 1..4
    bool reversedZ = true;        // cache renders use glClipControl(ZERO_TO_ONE), depth cleared to 0,
                                  // GL_GREATER: float depth keeps its precision far away
    bool objectIds = false;       // R32UI object-id target; a lookup also compares ids
    bool age = false;             // R16UI target: frames since each entry was computed
    bool stats = true;            // R8UI per-pixel outcome target (hit / miss reason), counted
                                  // asynchronously and drawn by visualize()
    bool depthInPayload = false;  // compare against linear depth stored in payload 0's last channel
                                  // (alpha; green for RG) instead of the depth texture: the
                                  // chapter's single-render-target trick, one fetch for the test
                                  // and the value. Needs payload 0 in RG16F/RG32F/RGBA16F/RGBA32F;
                                  // the shader writes rrc_currentLinearDepth() there
    bool bilinearDepth = true;    // bilinear cached-depth fetch: across a discontinuity the
                                  // blend fails the test by itself (chapter section 6.4.4)
    float depthTolerance = 0.01f; // relative tolerance on LINEAR view depth, see docs/cache.md
    float slopeTolerance = 1.0f;  // plus this many times the depth change across one pixel
    float resampleSnap = 1.0f / 512.0f; // a Bilinear/Bicubic payload fetch whose reprojected
                                  // position lies within this many texels of a texel centre (both
                                  // axes) reads that texel exactly: a static view then copies its
                                  // cache bit for bit instead of drifting through float noise in
                                  // the reprojection (docs/stability.md). 0: off. Below 0.5.
                                  // That noise is ~1 float ulp of the texel coordinate (1.2e-4
                                  // at 1024 texels, 9.8e-4 at 8192): above 8192 use 1/256.
    float maxScale = 0.0f;        // force a miss when the lookup magnifies or minifies by more
                                  // than this factor (0: off, and compiled out of the lookup)
    bool stencil = true;          // depth buffer with stencil (GL_DEPTH32F_STENCIL8), which
                                  // TwoPass/ThreePass need with FrameDesc::depthPrepass; false
                                  // gives a plain GL_DEPTH_COMPONENT32F, ~1-2 ms cheaper per
                                  // 1024x768 frame on llvmpipe (clears, depth test and writes),
                                  // for caches used with OnePass or without a prepass only
    bool refresh = false;         // lookups honour FrameDesc::refresh; off compiles the refresh
                                  // schedule out (it costs even when no policy is active)
    glm::vec4 clearColor{0.0f};   // payload value where nothing was drawn
    int firstTextureUnit = 8;     // the cache binds its textures to units from here on
    int uniformBinding = 7;       // binding point of the rrc_CacheBlock uniform block
};

struct FrameDesc {
    glm::dmat4 view{1.0};
    glm::dmat4 projection{1.0};   // perspective; near/far are derived from it
    RefreshDesc refresh{};        // needs CacheDesc::refresh unless the policy is None
    float lambda = 0.6f;          // recursive filter weight for rrc_blend (0 <= lambda < 1)
    bool forcedMisses = false;    // the shaders force misses (never-cache objects, predicates):
                                  // a frame where nothing moved then still needs its miss pass
    bool objectsMoved = true;     // false when no object moved since the cache was written
                                  // (e.g. from MotionHistory::anyMoved())
    bool depthPrepass = true;     // TwoPass/ThreePass: a depth-only pass first, so the lookup and
                                  // miss passes shade each pixel once (GL_EQUAL) and the miss pass
                                  // finds its pixels by stencil; a scene without overdraw does not
                                  // need it (OnePass always has one)
    bool skipEmptyMissPass = true;// TwoPass/ThreePass: a depth-only probe pass counts the pixels
                                  // left to the miss pass, which is not issued when none are
                                  // (occlusion query + conditional render); false saves the probe
};

enum class ControlFlow {
    OnePass,    // depth prepass, then one shading pass branching between hit and miss (fig. 6.5a)
    TwoPass,    // lookup pass shades hits and discards misses; the miss pass runs only on the
                // pixels left (fig. 6.5b, by stencil after a depth prepass, else by the depth
                // test); skipped entirely when nothing missed. With the outcome target
                // (CacheDesc::stats) the stencil comes from it through a full-screen pass, so the
                // lookup pass keeps early depth testing: hits must call rrc_writeCache (a hit the
                // outcome target does not record is shaded again by the miss pass)
    ThreePass,  // as TwoPass writing payloads only, then a full-screen pass shades from them
};

enum class Pass {
    DepthPrepass,  // depth only (colour writes are masked)
    Shade,         // OnePass: lookup and branch
    Lookup,        // Two/ThreePass: lookup; hit -> write, miss -> discard
    Probe,         // Two/ThreePass without the outcome target (CacheDesc::stats off): depth
                   // only, counts pixels left for the miss pass (with it, the library counts them)
    Miss,          // Two/ThreePass: the full computation
    Resolve,       // ThreePass: full-screen pass from the payloads (bind them with bindPayloads)
};

std::string_view passName(Pass pass);

// Per-pixel outcomes as stored in the stats target (and counted in Stats).
enum class Outcome : uint8_t { Empty = 0, Hit, Offscreen, Disoccluded, IdMismatch, Forced, Refreshed, Invalid };

struct Stats {
    uint64_t frame = 0;       // the frame these counts belong to
    uint64_t hits = 0;
    uint64_t misses = 0;      // offscreen + disoccluded + id mismatch + invalid
    uint64_t forced = 0;
    uint64_t refreshed = 0;
    uint64_t counts[8] = {};  // per Outcome
    bool valid = false;       // false until a frame's counts have arrived
    double hitRate() const {
        const uint64_t total = hits + misses + forced + refreshed;
        return total ? static_cast<double>(hits) / static_cast<double>(total) : 0.0;
    }
};

// How the implementation rounds a fragment shader's float output when it is stored into a
// colour format (measured by probeStoreRounding). llvmpipe truncates GL_RGBA16F and
// GL_R11F_G11F_B10F stores, rounds GL_RGBA8 to nearest and stores GL_RGB10_A2 about as
// floor(x * 1024) (Other); GPUs round to nearest.
enum class StoreRounding {
    Exact,        // 32-bit float and integer formats: nothing to round
    Nearest,      // to the nearest representable value
    TowardZero,   // truncation
    Other,        // anything else, or different in different parts of the range
};
std::string_view storeRoundingName(StoreRounding rounding);

// Renders values between two representable neighbours of `format` into a 1x1 target and reads
// them back. A diagnostic (it builds a program: tens of ms on llvmpipe): rrc_storeAmortized
// (shaders/rrc/blend.glsl) rounds onto the format's grid itself, so the cache's amortization is
// unbiased whichever way the store rounds. CacheInvalidDesc for formats a payload cannot have.
// Restores the framebuffer, viewport, program and vertex array bindings it changes.
Result<StoreRounding> probeStoreRounding(GLenum format);

class Cache {
public:
    // Validates the descriptor (CacheInvalidDesc / CacheTooLarge) and creates the targets.
    static Result<Cache> create(const CacheDesc& desc);

    Cache();
    Cache(Cache&&) noexcept;
    Cache& operator=(Cache&&) noexcept;
    ~Cache();

    // Swaps the targets (the last render becomes the cache), records the cache-time view and
    // uploads the cache block. Fails (CacheNonFinite) on non-finite or singular matrices, leaving
    // the cache unchanged.
    Result<void> beginFrame(const FrameDesc& frame);
    // Runs the passes of `flow` into the current targets, calling `draw` for each with the GL
    // state set (framebuffer, viewport, depth function and writes, masks, queries).
    Result<void> render(ControlFlow flow, const std::function<void(Pass)>& draw);
    // Starts the asynchronous stats count of this frame.
    void endFrame();

    // Everything misses next frame (camera cut). Resizing invalidates too.
    void invalidate();
    Result<void> resize(int width, int height);

    // The defines a program that uses the cache snippets must be composed with.
    std::vector<Define> defines() const;
    // Binds the previous (cache) textures to their units and the cache block: done by render()
    // itself; call it when you draw outside render().
    void bindForLookup() const;
    // Binds the CURRENT payload textures (the ones render() just wrote) for a Resolve pass.
    void bindPayloads(int firstUnit) const;
    // Sets rrc_prevMVP, rrc_objectId and rrc_drawFlags of `program` (skips unused ones).
    void setDrawUniforms(GLuint program, const DrawMatrices& matrices, uint32_t objectId = 0,
                         bool neverCache = false) const;
    DrawMatrices drawMatrices(const glm::dmat4& model, const glm::dmat4& prevModel) const;

    // Writes hits green, misses red, forced misses and refreshes blue, empty black (figs 6.1, 6.6d)
    // into `target` (RGBA8 of the cache's size, created when empty).
    void visualize(Texture& target) const;

    // Counts of the newest frame whose results have arrived, without waiting for the GPU.
    Stats stats() const;
    // Waits for every pending count (tests, benchmarks).
    Stats finishStats();

    const CacheDesc& desc() const;
    int width() const;
    int height() const;
    uint64_t frame() const;
    bool valid() const;          // false after invalidate() until a frame was rendered
    bool staticFrame() const;    // this frame: nothing moved, nothing refreshed, nothing forced
    GLuint payload(int index) const;          // current (being written / just written)
    GLuint previousPayload(int index) const;  // the cache being read
    GLuint depth() const;
    GLuint previousDepth() const;
    GLuint outcomes() const;                  // current R8UI outcome target (0 without stats)
    GLuint framebuffer() const;               // current target framebuffer
    const ViewState& view() const;
    const ViewState& cacheTimeView() const;

    struct Impl;

private:
    std::unique_ptr<Impl> impl_;
};

} // namespace rrc
