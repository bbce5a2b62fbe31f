// Backend selection and the parts of Context every backend shares (GL loading, debug output).
#include "context_impl.hpp"

#include <rrc/debug.hpp>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <string>

namespace rrc {
namespace {

// glad's pointers belong to one provider; they must be reloaded when another one becomes current.
const Context::Impl* loadedFor = nullptr;
Backend loadedBackend = Backend::Auto;

Result<std::unique_ptr<Context::Impl>> createFor(Backend backend, const ContextDesc& desc) {
    switch (backend) {
    case Backend::Egl: return createEglContext(desc);
    case Backend::OSMesa: return createOSMesaContext(desc);
    case Backend::Glfw: return createGlfwContext(desc);
    case Backend::Auto: break;
    }
    if (displayAvailable())
        if (auto glfw = createGlfwContext(desc)) return glfw;
    if (auto egl = createEglContext(desc)) return egl;
    return createOSMesaContext(desc);
}

} // namespace

std::string_view backendName(Backend backend) {
    switch (backend) {
    case Backend::Auto: return "auto";
    case Backend::Egl: return "egl";
    case Backend::OSMesa: return "osmesa";
    case Backend::Glfw: return "glfw";
    }
    return "?";
}

Result<Backend> parseBackend(std::string_view name) {
    std::string lower(name);
    std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return std::tolower(c); });
    for (Backend b : {Backend::Auto, Backend::Egl, Backend::OSMesa, Backend::Glfw})
        if (lower == backendName(b)) return b;
    return fail(LogId::BackendUnknown, "unknown GL backend '" + std::string(name) + "' (expected auto, egl, osmesa or glfw)");
}

Result<Context> Context::create(const ContextDesc& desc) {
    Backend backend = desc.backend;
    if (backend == Backend::Auto)
        if (const char* env = std::getenv("RRC_GL_BACKEND"); env && *env) {
            auto parsed = parseBackend(env);
            if (!parsed) return parsed.error();
            backend = parsed.value();
        }
    auto impl = createFor(backend, desc);
    if (!impl) return impl.error();
    Context context(std::move(impl).value());
    if (auto r = context.makeCurrent(); !r) return r.error();
    installDebugOutput();
    return context;
}

Context::Context(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Context::Context(Context&&) noexcept = default;
Context& Context::operator=(Context&&) noexcept = default;
Context::~Context() {
    if (impl_ && loadedFor == impl_.get()) loadedFor = nullptr;
}

Backend Context::backend() const { return impl_->backend(); }

Result<void> Context::makeCurrent() {
    const std::string name(backendName(impl_->backend()));
    if (!impl_->makeCurrentRaw())
        return fail(LogId::ContextCreateFailed, name + ": make-current failed");
    if (loadedFor != impl_.get()) {
        if (loadedBackend != impl_->backend() || loadedFor == nullptr) {
            if (auto r = loadGL(impl_->loader()); !r)
                return fail(LogId::ContextCreateFailed, name + ": " + r.error().message);
            loadedBackend = impl_->backend();
        }
        loadedFor = impl_.get();
    }
    return {};
}

GLFWwindow* Context::window() const { return impl_->window(); }
void Context::swapBuffers() { impl_->swapBuffers(); }
bool Context::shouldClose() const { return impl_->shouldClose(); }
void Context::pollEvents() { impl_->pollEvents(); }
std::string Context::renderer() const {
    const auto* text = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    return text ? text : "";
}

} // namespace rrc
