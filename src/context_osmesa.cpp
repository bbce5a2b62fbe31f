// OSMesa backend: Mesa's off-screen GL, rendering into a client-memory colour buffer.
#include "context_impl.hpp"

#include <GL/osmesa.h>

#include <vector>

namespace rrc {
namespace {

struct OSMesaBackend final : Context::Impl {
    OSMesaContext context = nullptr;
    std::vector<unsigned char> buffer;  // the default framebuffer; rrc renders into FBOs
    int width = 1, height = 1;

    ~OSMesaBackend() override {
        if (context) OSMesaDestroyContext(context);
    }
    Backend backend() const override { return Backend::OSMesa; }
    bool makeCurrentRaw() override {
        return OSMesaMakeCurrent(context, buffer.data(), GL_UNSIGNED_BYTE, width, height);
    }
    GLADloadfunc loader() const override {
        return [](const char* name) { return reinterpret_cast<GLADapiproc>(OSMesaGetProcAddress(name)); };
    }
};

} // namespace

Result<std::unique_ptr<Context::Impl>> createOSMesaContext(const ContextDesc& desc) {
    auto ctx = std::make_unique<OSMesaBackend>();
    const int attributes[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 24,
                              OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                              OSMESA_CONTEXT_MAJOR_VERSION, 4, OSMESA_CONTEXT_MINOR_VERSION, 5, 0};
    ctx->context = OSMesaCreateContextAttribs(attributes, nullptr);
    if (!ctx->context)
        return fail(LogId::ContextCreateFailed, "OSMesa: OSMesaCreateContextAttribs(GL 4.5 core) failed");
    ctx->width = std::max(desc.width, 1);
    ctx->height = std::max(desc.height, 1);
    ctx->buffer.assign(static_cast<size_t>(ctx->width) * ctx->height * 4, 0);
    return std::unique_ptr<Context::Impl>(std::move(ctx));
}

} // namespace rrc
