// EGL backend: a real GPU through EGL_EXT_platform_device when one exists, otherwise Mesa's
// surfaceless platform (llvmpipe). No window system and no /dev/dri needed.
#include "context_impl.hpp"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstring>
#include <string>
#include <vector>

namespace rrc {
namespace {

std::string eglErrorName(EGLint error) {
    switch (error) {
#define RRC_CASE(e) case e: return #e;
        RRC_CASE(EGL_SUCCESS) RRC_CASE(EGL_NOT_INITIALIZED) RRC_CASE(EGL_BAD_ACCESS)
        RRC_CASE(EGL_BAD_ALLOC) RRC_CASE(EGL_BAD_ATTRIBUTE) RRC_CASE(EGL_BAD_CONFIG)
        RRC_CASE(EGL_BAD_CONTEXT) RRC_CASE(EGL_BAD_CURRENT_SURFACE) RRC_CASE(EGL_BAD_DISPLAY)
        RRC_CASE(EGL_BAD_MATCH) RRC_CASE(EGL_BAD_NATIVE_PIXMAP) RRC_CASE(EGL_BAD_NATIVE_WINDOW)
        RRC_CASE(EGL_BAD_PARAMETER) RRC_CASE(EGL_BAD_SURFACE) RRC_CASE(EGL_CONTEXT_LOST)
#undef RRC_CASE
    default: return "EGL error " + std::to_string(error);
    }
}

Error eglFailure(const char* call) {
    return fail(LogId::ContextCreateFailed, std::string("EGL: ") + call + " failed: " + eglErrorName(eglGetError()));
}

bool hasExtension(const char* list, const char* name) {
    if (!list) return false;
    const size_t n = std::strlen(name);
    for (const char* p = std::strstr(list, name); p; p = std::strstr(p + n, name))
        if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
    return false;
}

// A hardware device (one without EGL_MESA_device_software), or EGL_NO_DISPLAY.
EGLDisplay hardwareDisplay(PFNEGLGETPLATFORMDISPLAYEXTPROC getPlatformDisplay) {
    auto queryDevices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
    auto queryDeviceString = reinterpret_cast<PFNEGLQUERYDEVICESTRINGEXTPROC>(eglGetProcAddress("eglQueryDeviceStringEXT"));
    if (!queryDevices || !queryDeviceString) return EGL_NO_DISPLAY;
    EGLDeviceEXT devices[16];
    EGLint count = 0;
    if (!queryDevices(16, devices, &count)) return EGL_NO_DISPLAY;
    for (EGLint i = 0; i < count; ++i) {
        const char* extensions = queryDeviceString(devices[i], EGL_EXTENSIONS);
        if (hasExtension(extensions, "EGL_MESA_device_software")) continue;
        EGLDisplay display = getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
        if (display != EGL_NO_DISPLAY && eglInitialize(display, nullptr, nullptr)) return display;
    }
    return EGL_NO_DISPLAY;
}

struct EglContext final : Context::Impl {
    EGLDisplay display = EGL_NO_DISPLAY;
    EGLContext context = EGL_NO_CONTEXT;

    ~EglContext() override {
        if (context != EGL_NO_CONTEXT) {
            if (eglGetCurrentContext() == context) eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
            eglDestroyContext(display, context);
        }
        // The display stays initialised: EGL displays are process-wide and shared by contexts.
    }
    Backend backend() const override { return Backend::Egl; }
    bool makeCurrentRaw() override { return eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context); }
    GLADloadfunc loader() const override { return reinterpret_cast<GLADloadfunc>(eglGetProcAddress); }
};

} // namespace

Result<std::unique_ptr<Context::Impl>> createEglContext(const ContextDesc& desc) {
    auto getPlatformDisplay = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (!getPlatformDisplay)
        return fail(LogId::ContextCreateFailed, "EGL: eglGetPlatformDisplayEXT unavailable (no EGL_EXT_platform_base)");
    auto ctx = std::make_unique<EglContext>();
    ctx->display = hardwareDisplay(getPlatformDisplay);
    if (ctx->display == EGL_NO_DISPLAY) {
        ctx->display = getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        if (ctx->display == EGL_NO_DISPLAY) return eglFailure("eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA)");
        if (!eglInitialize(ctx->display, nullptr, nullptr)) return eglFailure("eglInitialize");
    }
    if (!eglBindAPI(EGL_OPENGL_API)) return eglFailure("eglBindAPI(EGL_OPENGL_API)");
    const EGLint attributes[] = {
        EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
        EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
        EGL_CONTEXT_OPENGL_DEBUG, desc.debugContext ? EGL_TRUE : EGL_FALSE, EGL_NONE};
    ctx->context = eglCreateContext(ctx->display, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes);
    if (ctx->context == EGL_NO_CONTEXT) return eglFailure("eglCreateContext(GL 4.5 core)");
    return std::unique_ptr<Context::Impl>(std::move(ctx));
}

} // namespace rrc
