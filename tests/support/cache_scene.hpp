// A scene with analytically known answers for cache tests: unit quads placed by double-precision
// model matrices, whose payload is the world position of the surface point (linear over a quad,
// so bilinear resampling of it is exact away from edges). One program per pass of each flow.
#pragma once
#include <rrc/cache.hpp>
#include <rrc/projection.hpp>

#include <glm/glm.hpp>

#include <span>
#include <string>
#include <vector>

namespace rrc::test {

struct Object {
    glm::dmat4 model{1.0};
    glm::dmat4 prevModel{1.0};
    uint32_t id = 1;
    bool neverCache = false;
    bool forceMiss = false;   // the caller-defined predicate of the test shader
};

struct Camera {
    glm::dvec3 eye{0.0};
    glm::dvec3 target{0.0, 0.0, -1.0};
    double fovy = 1.0;
    double near = 0.1;
    double far = kInfiniteFar;
    glm::dmat4 view() const;
    glm::dmat4 projection(double aspect, bool reversedZ) const;
};

// A quad spanning [-sx,sx]x[-sy,sy] at z (world), as a model matrix of the unit quad.
glm::dmat4 quadAt(glm::dvec3 center, glm::dvec2 halfSize);

enum class Shading {
    WorldPosition,   // miss: world position; hit: cached payload
    Amortized,       // every pixel: fresh noise sample blended into the cached one (rrc_blend)
};

// What the test scenes share: unit quads (`a_corner` in [-1, 1]^2; the vertex shader outputs
// v_world and v_local) drawn with one program per pass of each flow from one fragment source
// (PASS_LOOKUP / PASS_MISS / neither), a depth-only program, the ThreePass resolve, and the
// frame loop. Subclasses supply the fragment source and their uniforms.
class QuadScene {
public:
    virtual ~QuadScene() = default;
    std::vector<Pass> passes;   // passes of the last frame, in order
    Texture resolved;           // ThreePass: the resolve output (RGBA32F, the cache's size)

protected:
    QuadScene(const Cache& cache, const std::string& fragment, std::vector<Define> defines);
    // beginFrame (with `f`, whose view and projection the caller set) + render + endFrame.
    // Returns false when beginFrame failed (a failed render also fails the test).
    bool renderFrame(Cache& cache, ControlFlow flow, std::span<const Object> objects, const FrameDesc& f);
    virtual void setFrameUniforms(GLuint /*program*/, uint32_t /*frame*/) const {}
    virtual void setObjectUniforms(GLuint /*program*/, const Object& /*object*/) const {}
    virtual void beforeRender() {}

private:
    ShaderLibrary library_;
    Program lookup_, miss_, shade_, depthOnly_, resolve_;
    Buffer vertices_;
    VertexArray vao_, emptyVao_;
    Framebuffer resolveFramebuffer_;
    int resolveWidth_ = 0, resolveHeight_ = 0;
    void drawObjects(const Cache& cache, GLuint program, std::span<const Object> objects, uint32_t frame) const;
};

// Payload: the world position of the surface point (linear over a quad, so bilinear resampling
// of it is exact away from edges), or amortized noise.
class CacheScene : public QuadScene {
public:
    CacheScene(const Cache& cache, Shading shading = Shading::WorldPosition, std::vector<Define> extra = {});

    // beginFrame + render + endFrame. Returns false when beginFrame failed.
    bool frame(Cache& cache, ControlFlow flow, const Camera& camera, std::span<const Object> objects,
               FrameDesc frameDesc = {});

    // Fragments the miss program ran for (atomic counter in the shader), reset every frame.
    uint32_t missFragments() const;
    // A fresh-sample value added to every pixel's noise (NaN/Inf injection tests).
    float sampleOffset = 0.0f;

private:
    Buffer counter_;
    void setFrameUniforms(GLuint program, uint32_t frame) const override;
    void setObjectUniforms(GLuint program, const Object& object) const override;
    void beforeRender() override;
};

// Whole-texture readbacks in GL order (row 0 at the bottom).
std::vector<glm::vec4> readRGBA(GLuint texture);
std::vector<uint32_t> readUint(GLuint texture);   // R8UI, R16UI, R32UI
std::vector<float> readDepthTexture(GLuint texture);

} // namespace rrc::test
