// Internal: what each context backend implements.
#pragma once
#include <rrc/context.hpp>
#include <rrc/gl.hpp>

namespace rrc {

struct Context::Impl {
    virtual ~Impl() = default;
    virtual Backend backend() const = 0;
    virtual bool makeCurrentRaw() = 0;          // provider's make-current; false on failure
    virtual GLADloadfunc loader() const = 0;    // provider's getProcAddress
    virtual GLFWwindow* window() const { return nullptr; }
    virtual void swapBuffers() {}
    virtual bool shouldClose() const { return false; }
    virtual void pollEvents() {}
};

Result<std::unique_ptr<Context::Impl>> createEglContext(const ContextDesc& desc);
Result<std::unique_ptr<Context::Impl>> createOSMesaContext(const ContextDesc& desc);
Result<std::unique_ptr<Context::Impl>> createGlfwContext(const ContextDesc& desc);

} // namespace rrc
