// Internal state of rrc::Cache, shared by cache.cpp (targets), cache_frame.cpp (frames and
// control flow) and cache_stats.cpp (outcome counts and visualisation).
#pragma once
#include <rrc/cache.hpp>
#include <rrc/projection.hpp>

#include <array>

namespace rrc {

// Texture units relative to CacheDesc::firstTextureUnit.
inline constexpr int kDepthUnitOffset = 0, kIdUnitOffset = 1, kAgeUnitOffset = 2, kPayloadUnitOffset = 3;

struct CacheTargets {
    std::vector<Texture> payloads;
    Texture depth, ids, age, outcomes;
    Framebuffer framebuffer;
    Framebuffer stencilOnly;  // the depth-stencil attachment alone: the miss-marking pass
    bool rendered = false;   // holds a complete render usable as a cache
};

// std140 layout of rrc_CacheBlock (shaders/rrc/cache_block.glsl).
struct CacheBlock {
    float size[4];
    float depth[4];
    float tolerance[4];
    uint32_t frameInfo[4];
    float refreshInfo[4];
};

struct StatsSlot {
    Buffer counts;
    GLsync fence = nullptr;
    uint64_t frame = 0;
};

struct Cache::Impl {
    CacheDesc desc;
    std::array<CacheTargets, 2> targets;
    int current = 0;
    ViewState view, cacheView;
    DepthRange cacheRange;        // near/far of the cache-time projection
    FrameDesc frameDesc;
    uint64_t frame = 0;
    bool begun = false;           // a frame is in progress
    bool invalidated = true;
    bool staticFrame = false;
    Buffer block;
    VertexArray emptyVao;
    Query probe;
    // Stats: a ring of count buffers, read when their fence has signalled.
    std::array<StatsSlot, 3> slots;
    int nextSlot = 0;
    Stats latest;
    Program statsProgram, visualizeProgram, markProgram;

    CacheTargets& cur() { return targets[current]; }
    const CacheTargets& cur() const { return targets[current]; }
    const CacheTargets& prev() const { return targets[1 - current]; }
    bool previousValid() const { return !invalidated && prev().rendered; }
    int unit(int offset) const { return desc.firstTextureUnit + offset; }

    Result<void> createTargets();
    void uploadBlock();
    void clearCurrent();
    void collectStats(bool wait);
    // Two-pass flow with an outcome target: stencil 1 -> 2 where the lookup did not hit, counted
    // by the probe query when `probe`. Leaves the cache framebuffer bound.
    Result<void> markMisses(bool probe);
    ~Impl();
};

bool isIntegerFormat(GLenum format);
// Makes `previous` (a GL_CURRENT_PROGRAM read earlier) current again, or no program when it no
// longer exists: an application may delete its current program (ImGui does at shutdown), which
// then lives only until another program is made current, i.e. until the library's own.
void restoreProgram(GLint previous);
// A program from the library's own snippets (rrc/internal/...); null names are left out.
Result<Program> internalProgram(const char* vertex, const char* fragment, const char* compute);

} // namespace rrc
