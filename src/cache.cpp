// rrc::Cache creation: descriptor validation, the double-buffered targets, defines for programs.
#include "cache_impl.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace rrc {
namespace {

struct FormatInfo { GLenum format; const char* name; };
constexpr FormatInfo kFormats[] = {
    {GL_RGBA8, "GL_RGBA8"}, {GL_RGBA16F, "GL_RGBA16F"}, {GL_RGBA32F, "GL_RGBA32F"}, {GL_R32F, "GL_R32F"},
    {GL_RG16F, "GL_RG16F"}, {GL_RG32F, "GL_RG32F"}, {GL_R16F, "GL_R16F"}, {GL_R11F_G11F_B10F, "GL_R11F_G11F_B10F"},
    {GL_RGB10_A2, "GL_RGB10_A2"}, {GL_R32UI, "GL_R32UI"}, {GL_RG32UI, "GL_RG32UI"}, {GL_RGBA32UI, "GL_RGBA32UI"},
};

// How rrc_storeAmortized (shaders/rrc/blend.glsl) rounds for a payload format: 0 = stores are
// exact, 1 = UNORM with `bits` per channel, 2 = small float with `bits` mantissa bits per channel
// (0: channel absent) and largest finite values `max`.
struct StoreQuantization { int kind; const char* bits; const char* max; };

StoreQuantization storeQuantization(GLenum format) {
    switch (format) {
    case GL_RGBA8: return {1, "ivec4(8, 8, 8, 8)", "vec4(1.0)"};
    case GL_RGB10_A2: return {1, "ivec4(10, 10, 10, 2)", "vec4(1.0)"};
    case GL_RGBA16F: return {2, "ivec4(10, 10, 10, 10)", "vec4(65504.0)"};
    case GL_RG16F: return {2, "ivec4(10, 10, 0, 0)", "vec4(65504.0)"};
    case GL_R16F: return {2, "ivec4(10, 0, 0, 0)", "vec4(65504.0)"};
    case GL_R11F_G11F_B10F: return {2, "ivec4(6, 6, 5, 0)", "vec4(65024.0, 65024.0, 64512.0, 0.0)"};
    default: return {0, "ivec4(0)", "vec4(0.0)"};   // 32-bit float and integer formats
    }
}

std::string hex(GLenum value) {
    static const char digits[] = "0123456789ABCDEF";
    std::string out;
    do { out.insert(out.begin(), digits[value & 15u]); value >>= 4; } while (value);
    return "0x" + out;
}

bool supportedFormat(GLenum format) {
    return std::any_of(std::begin(kFormats), std::end(kFormats), [&](auto& f) { return f.format == format; });
}

// The payload-0 channel that holds linear depth with CacheDesc::depthInPayload: the last one of
// a float format with room for it (nullptr: none).
const char* depthChannel(GLenum format) {
    switch (format) {
    case GL_RG16F: case GL_RG32F: return "g";
    case GL_RGBA16F: case GL_RGBA32F: return "a";
    default: return nullptr;
    }
}

Texture makeTexture(GLenum format, int width, int height, GLenum filter) {
    Texture t = createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(t.id(), 1, format, width, height);
    glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, filter);
    glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, filter);
    glTextureParameteri(t.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(t.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return t;
}

Result<void> validate(const CacheDesc& d) {
    auto bad = [](std::string why) { return fail(LogId::CacheInvalidDesc, "CacheDesc: " + why); };
    if (d.width <= 0 || d.height <= 0)
        return bad("width and height must be positive (got " + std::to_string(d.width) + "x" + std::to_string(d.height) + ")");
    GLint maxSize = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
    if (d.width > maxSize || d.height > maxSize)
        return fail(LogId::CacheTooLarge, "CacheDesc: " + std::to_string(d.width) + "x" + std::to_string(d.height) +
                                              " exceeds GL_MAX_TEXTURE_SIZE " + std::to_string(maxSize));
    if (d.payloads.empty() || d.payloads.size() > 4)
        return bad("1 to 4 payloads required (got " + std::to_string(d.payloads.size()) + ")");
    for (size_t i = 0; i < d.payloads.size(); ++i) {
        const auto& p = d.payloads[i];
        if (!supportedFormat(p.format)) return bad("payload " + std::to_string(i) + ": unsupported format " + hex(p.format));
        if (isIntegerFormat(p.format) && p.resample != Resample::Nearest)
            return bad("payload " + std::to_string(i) + ": integer formats resample Nearest only");
    }
    if (d.depthInPayload && !depthChannel(d.payloads[0].format))
        return bad("depthInPayload needs payload 0 in GL_RG16F, GL_RG32F, GL_RGBA16F or GL_RGBA32F (got " +
                   hex(d.payloads[0].format) + ")");
    if (!(d.depthTolerance > 0.0f) || !std::isfinite(d.depthTolerance))
        return bad("depthTolerance must be finite and > 0 (got " + std::to_string(d.depthTolerance) + ")");
    if (!(d.slopeTolerance >= 0.0f) || !std::isfinite(d.slopeTolerance)) return bad("slopeTolerance must be finite and >= 0");
    if (!(d.maxScale >= 0.0f) || !std::isfinite(d.maxScale)) return bad("maxScale must be finite and >= 0");
    if (!(d.resampleSnap >= 0.0f && d.resampleSnap < 0.5f)) return bad("resampleSnap must be in [0, 0.5)");
    GLint units = 0;
    glGetIntegerv(GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS, &units);
    if (d.firstTextureUnit < 0 || d.firstTextureUnit + kPayloadUnitOffset + 4 > units)
        return bad("firstTextureUnit out of range");
    GLint bindings = 0;
    glGetIntegerv(GL_MAX_UNIFORM_BUFFER_BINDINGS, &bindings);
    if (d.uniformBinding < 0 || d.uniformBinding >= bindings) return bad("uniformBinding out of range");
    return {};
}

} // namespace

void restoreProgram(GLint previous) {
    const auto program = static_cast<GLuint>(previous);
    glUseProgram(program != 0 && glIsProgram(program) ? program : 0);
}

bool isIntegerFormat(GLenum format) {
    return format == GL_R32UI || format == GL_RG32UI || format == GL_RGBA32UI;
}

Result<void> Cache::Impl::createTargets() {
    for (auto& t : targets) {
        t = CacheTargets{};
        t.framebuffer = createFramebuffer();
        std::vector<GLenum> drawBuffers;
        auto attach = [&](const Texture& texture) {
            const GLenum attachment = GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(drawBuffers.size());
            glNamedFramebufferTexture(t.framebuffer.id(), attachment, texture.id(), 0);
            drawBuffers.push_back(attachment);
        };
        for (const auto& p : desc.payloads) {
            t.payloads.push_back(makeTexture(p.format, desc.width, desc.height, isIntegerFormat(p.format) ? GL_NEAREST : GL_LINEAR));
            attach(t.payloads.back());
        }
        if (desc.objectIds) { t.ids = makeTexture(GL_R32UI, desc.width, desc.height, GL_NEAREST); attach(t.ids); }
        if (desc.age) { t.age = makeTexture(GL_R16UI, desc.width, desc.height, GL_NEAREST); attach(t.age); }
        if (desc.stats) { t.outcomes = makeTexture(GL_R8UI, desc.width, desc.height, GL_NEAREST); attach(t.outcomes); }
        // Stencil marks the pixels the lookup pass resolved, for the miss pass after a prepass.
        const GLenum depthFormat = desc.stencil ? GL_DEPTH32F_STENCIL8 : GL_DEPTH_COMPONENT32F;
        const GLenum depthAttachment = desc.stencil ? GL_DEPTH_STENCIL_ATTACHMENT : GL_DEPTH_ATTACHMENT;
        t.depth = makeTexture(depthFormat, desc.width, desc.height, desc.bilinearDepth ? GL_LINEAR : GL_NEAREST);
        glNamedFramebufferTexture(t.framebuffer.id(), depthAttachment, t.depth.id(), 0);
        glNamedFramebufferDrawBuffers(t.framebuffer.id(), static_cast<GLsizei>(drawBuffers.size()), drawBuffers.data());
        if (auto r = checkFramebuffer(t.framebuffer, "rrc::Cache target"); !r) return r;
        if (desc.stats && desc.stencil) {
            t.stencilOnly = createFramebuffer();
            glNamedFramebufferTexture(t.stencilOnly.id(), GL_DEPTH_STENCIL_ATTACHMENT, t.depth.id(), 0);
            glNamedFramebufferDrawBuffer(t.stencilOnly.id(), GL_NONE);
            if (auto r = checkFramebuffer(t.stencilOnly, "rrc::Cache stencil target"); !r) return r;
        }
    }
    invalidated = true;
    return {};
}

Result<Cache> Cache::create(const CacheDesc& desc) {
    if (auto r = validate(desc); !r) return r.error();
    Cache cache;
    cache.impl_ = std::make_unique<Impl>();
    Impl& s = *cache.impl_;
    s.desc = desc;
    if (auto r = s.createTargets(); !r) return r.error();
    s.block = createBuffer();
    glNamedBufferStorage(s.block.id(), sizeof(CacheBlock), nullptr, GL_DYNAMIC_STORAGE_BIT);
    s.emptyVao = createVertexArray();
    s.probe = createQuery(GL_ANY_SAMPLES_PASSED);
    for (auto& slot : s.slots) {
        slot.counts = createBuffer();
        glNamedBufferStorage(slot.counts.id(), 8 * sizeof(uint32_t), nullptr, GL_DYNAMIC_STORAGE_BIT);
    }
    s.uploadBlock();
    return cache;
}

Cache::Cache() = default;
Cache::Cache(Cache&&) noexcept = default;
Cache& Cache::operator=(Cache&&) noexcept = default;
Cache::~Cache() = default;

Cache::Impl::~Impl() {
    for (auto& slot : slots)
        if (slot.fence) glDeleteSync(slot.fence);
}

Result<void> Cache::resize(int width, int height) {
    if (!impl_) return fail(LogId::CacheInvalidObject, "Cache::resize on an empty (moved-from or default) cache");
    CacheDesc d = impl_->desc;
    d.width = width;
    d.height = height;
    if (auto r = validate(d); !r) return r;
    impl_->desc = d;
    if (auto r = impl_->createTargets(); !r) return r;
    impl_->uploadBlock();
    return {};
}

void Cache::invalidate() {
    if (!impl_) { logError(LogId::CacheInvalidObject, "Cache::invalidate on an empty (moved-from or default) cache"); return; }
    impl_->invalidated = true;
    impl_->uploadBlock();
}

std::vector<Define> Cache::defines() const {
    if (!impl_) { logError(LogId::CacheInvalidObject, "Cache::defines on an empty (moved-from or default) cache"); return {}; }
    const CacheDesc& d = impl_->desc;
    std::vector<Define> out{{"RRC_CACHE_BINDING", std::to_string(d.uniformBinding)},
                            {"RRC_PAYLOAD_COUNT", std::to_string(d.payloads.size())},
                            {"RRC_DEPTH_UNIT", std::to_string(impl_->unit(kDepthUnitOffset))}};
    static const char* const fetch[] = {"rrc_sampleNearest", "rrc_sampleBilinear", "rrc_sampleBicubic"};
    const bool snap = d.resampleSnap > 0.0f &&
                      std::any_of(d.payloads.begin(), d.payloads.end(), [](const PayloadDesc& p) { return p.resample != Resample::Nearest; });
    if (snap) {
        // Snapped fetch (CacheDesc::resampleSnap): RRC_TEXEL is the position in texels relative to
        // texel centres, integral at a centre. Within the snap distance of one on both axes the
        // texel is fetched exactly: filtering at a position computed as the centre plus float
        // noise would mix in neighbours by ~1e-5 per frame, which llvmpipe's truncating float16
        // stores turn into a drift of the whole image (docs/stability.md).
        char snapDistance[32];
        std::snprintf(snapDistance, sizeof(snapDistance), "%.9g", static_cast<double>(d.resampleSnap));
        out.push_back({"RRC_SNAP_TEXELS", snapDistance});
        out.push_back({"RRC_TEXEL(s, uv)", "((uv) * vec2(textureSize(s, 0)) - 0.5)"});
        out.push_back({"RRC_SNAPPED(s, uv)",
                       "all(lessThanEqual(abs(RRC_TEXEL(s, uv) - round(RRC_TEXEL(s, uv))), vec2(RRC_SNAP_TEXELS)))"});
    }
    for (size_t i = 0; i < d.payloads.size(); ++i) {
        const std::string n = "RRC_PAYLOAD" + std::to_string(i);
        out.push_back({n + "_UNIT", std::to_string(impl_->unit(kPayloadUnitOffset + static_cast<int>(i)))});
        out.push_back({n + "_SAMPLER", isIntegerFormat(d.payloads[i].format) ? "usampler2D" : "sampler2D"});
        const char* f = fetch[static_cast<int>(d.payloads[i].resample)];
        if (snap && d.payloads[i].resample != Resample::Nearest)
            out.push_back({n + "_FETCH(s, uv)", std::string("(RRC_SNAPPED(s, uv) ? texelFetch(s, ivec2(round(RRC_TEXEL(s, uv))), 0) : ") +
                                                    f + "(s, uv))"});
        else
            out.push_back({n + "_FETCH", f});
        const StoreQuantization q = storeQuantization(d.payloads[i].format);
        out.push_back({n + "_QUANT", std::to_string(q.kind)});
        out.push_back({n + "_BITS", q.bits});
        out.push_back({n + "_MAX", q.max});
    }
    int location = static_cast<int>(d.payloads.size());
    if (d.objectIds) {
        out.push_back({"RRC_OBJECT_IDS"});
        out.push_back({"RRC_ID_UNIT", std::to_string(impl_->unit(kIdUnitOffset))});
        out.push_back({"RRC_ID_LOCATION", std::to_string(location++)});
    }
    if (d.age) {
        out.push_back({"RRC_AGE"});
        out.push_back({"RRC_AGE_UNIT", std::to_string(impl_->unit(kAgeUnitOffset))});
        out.push_back({"RRC_AGE_LOCATION", std::to_string(location++)});
    }
    if (d.stats) {
        out.push_back({"RRC_STATS"});
        out.push_back({"RRC_OUTCOME_LOCATION", std::to_string(location++)});
    }
    if (d.depthInPayload) {
        out.push_back({"RRC_DEPTH_IN_PAYLOAD"});
        out.push_back({"RRC_DEPTH_CHANNEL", depthChannel(d.payloads[0].format)});
    }
    if (d.refresh) out.push_back({"RRC_REFRESH"});
    if (d.maxScale > 0.0f) out.push_back({"RRC_MAX_SCALE"});
    if (!d.bilinearDepth) out.push_back({"RRC_NEAREST_DEPTH"});
    return out;
}

namespace {

const Cache::Impl* alive(const std::unique_ptr<Cache::Impl>& impl, const char* what) {
    if (!impl) logError(LogId::CacheInvalidObject, std::string(what) + " on an empty (moved-from or default) cache");
    return impl.get();
}

GLuint payloadOf(const std::unique_ptr<Cache::Impl>& impl, int i, bool previous, const char* what) {
    const Cache::Impl* s = alive(impl, what);
    if (!s) return 0;
    const int count = static_cast<int>(s->desc.payloads.size());
    if (i < 0 || i >= count) {
        logError(LogId::CacheBadArgument, std::string(what) + ": payload index " + std::to_string(i) +
                                              " out of range (the cache has " + std::to_string(count) + ")");
        return 0;
    }
    return (previous ? s->prev() : s->cur()).payloads[static_cast<size_t>(i)].id();
}

const CacheDesc kEmptyDesc{};
const ViewState kEmptyView{};

} // namespace

const CacheDesc& Cache::desc() const { return alive(impl_, "Cache::desc") ? impl_->desc : kEmptyDesc; }
int Cache::width() const { return impl_ ? impl_->desc.width : 0; }
int Cache::height() const { return impl_ ? impl_->desc.height : 0; }
uint64_t Cache::frame() const { return impl_ ? impl_->frame : 0; }
bool Cache::valid() const { return impl_ && impl_->previousValid(); }
bool Cache::staticFrame() const { return impl_ && impl_->staticFrame; }
GLuint Cache::payload(int i) const { return payloadOf(impl_, i, false, "Cache::payload"); }
GLuint Cache::previousPayload(int i) const { return payloadOf(impl_, i, true, "Cache::previousPayload"); }
GLuint Cache::depth() const { return alive(impl_, "Cache::depth") ? impl_->cur().depth.id() : 0; }
GLuint Cache::previousDepth() const { return alive(impl_, "Cache::previousDepth") ? impl_->prev().depth.id() : 0; }
GLuint Cache::outcomes() const { return alive(impl_, "Cache::outcomes") ? impl_->cur().outcomes.id() : 0; }
GLuint Cache::framebuffer() const { return alive(impl_, "Cache::framebuffer") ? impl_->cur().framebuffer.id() : 0; }
const ViewState& Cache::view() const { return alive(impl_, "Cache::view") ? impl_->view : kEmptyView; }
const ViewState& Cache::cacheTimeView() const { return alive(impl_, "Cache::cacheTimeView") ? impl_->cacheView : kEmptyView; }

} // namespace rrc
