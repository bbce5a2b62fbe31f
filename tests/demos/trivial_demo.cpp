// The trivial test demo: one shared state object captured by every callback (RAII: cleanup()
// drops the GL objects while the context is still current).
#include "trivial_demo.hpp"

#include <common/fullscreen.hpp>
#include <common/target.hpp>

#include <CLI/CLI.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <imgui.h>

#include <memory>
#include <optional>
#include <string>

namespace rrc::demo::test {
namespace {

constexpr const char* kFragment = R"(#version 450 core
// Marble or wood (WOOD) on a sphere of radius 4 around the eye, lit by one directional light;
// the second output marks where the specular term is strong.
#include <common/shaders/marble.glsl>
#include <common/shaders/lighting.glsl>
in vec2 demo_uv;
layout(location = 0) uniform mat4 u_invViewProj;
layout(location = 1) uniform vec3 u_eye;
layout(location = 2) uniform float u_time;
layout(location = 0) out vec4 o_color;
layout(location = 1) out vec4 o_vis;

void main() {
    vec4 far = u_invViewProj * vec4(demo_uv * 2.0 - 1.0, 0.5, 1.0);
    vec3 dir = normalize(far.xyz / far.w - u_eye);
    vec3 p = u_eye + 4.0 * dir + vec3(0.0, 0.0, 0.25 * u_time);
#ifdef WOOD
    vec3 albedo = demo_wood(p);
#else
    vec3 albedo = demo_marble(p);
#endif
    demo_Light light = demo_Light(vec3(0.3, 1.0, 0.5), vec3(0.9), vec3(0.15));
    demo_Shading s = demo_blinnPhong(albedo, -dir + 0.3 * vec3(demo_perlin(p * 3.0)), -dir, light, vec3(0.4), 24.0);
    o_color = vec4(demo_total(s), 1.0);
    o_vis = s.specular.g > 0.05 ? vec4(0.0, 0.0, 1.0, 1.0) : vec4(0.0, 0.6, 0.0, 1.0);
}
)";

struct State {
    Probe* probe = nullptr;
    int octaves = 5;
    std::string material = "marble";
    int builtOctaves = 0;
    std::optional<RenderTarget> target;
    std::optional<FullscreenPass> pass;

    Result<void> build(App& app) {
        auto pass = FullscreenPass::create(app.shaders(), "tests/trivial.frag",
                                           {{"RRC_DEMO_OCTAVES", std::to_string(octaves)},
                                            {"RRC_DEMO_NOISE_SEED", std::to_string(app.seed()) + "u"},
                                            {material == "wood" ? "WOOD" : "MARBLE"}});
        if (!pass) return pass.error();
        this->pass = std::move(pass).value();
        builtOctaves = octaves;
        return {};
    }
    Result<void> makeTarget(int width, int height) {
        auto t = RenderTarget::create({.width = width, .height = height, .colorFormats = {GL_RGBA16F, GL_RGBA8}, .depthFormat = 0});
        if (!t) return t.error();
        target = std::move(t).value();
        return {};
    }
};

} // namespace

DemoDesc trivialDemo(Probe* probe) {
    auto s = std::make_shared<State>();
    s->probe = probe;
    return {
        .name = "marble",
        .addOptions = [s](CLI::App& cli) {
            cli.add_option("--octaves", s->octaves, "noise octaves")->check(CLI::Range(1, 12));
            cli.add_option("--material", s->material, "marble or wood")->check(CLI::IsMember({"marble", "wood"}));
        },
        .init = [s](App& app) -> Result<void> {
            if (s->probe) ++s->probe->inits;
            if (s->probe && s->probe->failInit) return fail(LogId::SceneLoadFailed, "trivial demo: init failure requested");
            app.shaders().add("tests/trivial.frag", kFragment);
            app.setCameraPath(OrbitPath{.center = {0.0, 0.0, 0.0}, .radius = 3.0, .height = 1.0, .period = 4.0});
            if (auto r = s->build(app); !r) return r;
            return s->makeTarget(app.width(), app.height());
        },
        .frame = [s](App& app, const FrameInfo& info) {
            if (s->octaves != s->builtOctaves) (void)s->build(app);   // the gui slider moved
            const glm::mat4 invViewProj(glm::inverse(app.camera().viewProjection(app.aspect())));
            const glm::vec3 eye(app.camera().position);
            s->target->bind();
            glDisable(GL_DEPTH_TEST);
            glProgramUniformMatrix4fv(s->pass->program(), 0, 1, GL_FALSE, glm::value_ptr(invViewProj));
            glProgramUniform3fv(s->pass->program(), 1, 1, glm::value_ptr(eye));
            glProgramUniform1f(s->pass->program(), 2, static_cast<float>(info.time));
            s->pass->draw();
            if (s->probe) {
                ++s->probe->frames;
                if (s->probe->onFrame) s->probe->onFrame(app, info);
            }
        },
        .outputs = [s](App&) { return Outputs{.color = s->target->color(0), .visualization = s->target->color(1)}; },
        .stats = [s](App& app) {
            return Stats{{"octaves", static_cast<double>(s->builtOctaves)}, {"cached", app.mode() == Mode::Cached ? 1.0 : 0.0}};
        },
        .gui = [s](App&) {
            if (s->probe) ++s->probe->guiCalls;
            ImGui::SliderInt("octaves", &s->octaves, 1, 12);
        },
        .onResize = [s](App&, int width, int height) -> Result<void> {
            if (s->probe) s->probe->resizes.emplace_back(width, height);
            return s->makeTarget(width, height);
        },
        .cleanup = [s](App&) {
            if (s->probe) ++s->probe->cleanups;
            s->target.reset();
            s->pass.reset();
        },
    };
}

} // namespace rrc::demo::test
