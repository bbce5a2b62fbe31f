// rrc-shadows: shadow-map PCF with k Poisson taps rotated per pixel and frame (chapter section
// 6.5.5). --mode brute: plain k-tap PCF; --mode cached: the same k taps amortized through the
// reprojection cache with the recursive filter (--lambda, 0.75 by default), optionally blurred,
// remapped or thresholded (fig. 6.9). A box walks through the colonnade casting a moving shadow.
#include "shadow_renderer.hpp"
#include "shadow_scene.hpp"

#include "common/app.hpp"
#include "support/scene_draws.hpp"

#include <CLI/CLI.hpp>
#include <imgui.h>

namespace rrc::shadows {
std::span<const EmbeddedFile> shaders();
}

namespace {

using namespace rrc;
using namespace rrc::shadows;

struct State {
    ShadowSettings settings;
    std::string remap = "none", flow = "one-pass";
    demo::DrawScene scene;
    ShadowRenderer renderer;
    Texture visualization;
    Variant variant = Variant::Amortized;
    glm::dmat4 prevCaster{1.0};
    bool havePrev = false;
} state;

Result<void> initRenderer(demo::App& app) {
    return state.renderer.init(app.width(), app.height(), app.shaders(), state.scene.draws, state.scene.boundsMin,
                               state.scene.boundsMax, 2048, {.stencil = state.settings.flow == Flow::TwoPass});
}

demo::DemoDesc shadowsDemo() {
    demo::DemoDesc d;
    d.name = "shadows";
    d.addOptions = [](CLI::App& app) {
        app.add_option("--taps", state.settings.taps, "PCF taps per pixel and frame (k)")->check(CLI::Range(1, 256));
        app.add_option("--lambda", state.settings.lambda, "recursive filter weight")->check(CLI::Range(0.0, 0.99));
        app.add_flag("--blur", state.settings.blur, "depth-aware blur of the cached visibility");
        app.add_option("--remap", state.remap, "visibility remap")->check(CLI::IsMember({"none", "smoothstep", "threshold"}));
        app.add_option("--radius", state.settings.radius, "PCF radius, metres")->check(CLI::PositiveNumber);
        app.add_option("--flow", state.flow, "cached control flow")->check(CLI::IsMember({"single-pass", "one-pass", "two-pass"}));
    };
    d.init = [](demo::App& app) -> Result<void> {
        state.settings.remap = state.remap == "smoothstep" ? Remap::Smoothstep : state.remap == "threshold" ? Remap::Threshold : Remap::None;
        state.settings.flow = state.flow == "one-pass" ? Flow::OnePass : state.flow == "two-pass" ? Flow::TwoPass : Flow::SinglePass;
        state.settings.seed = app.seed();
        auto scene = demo::loadDrawScene(app.scenePath().empty() ? "assets/temple.glb" : app.scenePath());
        if (!scene) return scene.error();
        state.scene = std::move(scene).value();
        app.shaders().add(shadows::shaders());
        app.setCameraPath(cameraPath({state.scene.boundsMin, state.scene.boundsMax}));
        return initRenderer(app);
    };
    d.onResize = [](demo::App& app, int, int) { return initRenderer(app); };
    d.frame = [](demo::App& app, const demo::FrameInfo& info) {
        state.variant = app.mode() == demo::Mode::Brute ? Variant::Pcf : Variant::Amortized;
        const glm::dmat4 caster = casterModel(info.time);
        state.renderer.render(state.variant, state.settings,
                              {.view = app.camera().view(), .projection = app.camera().projection(app.aspect()),
                               .toLight = sunDirection(), .caster = caster,
                               .prevCaster = state.havePrev ? state.prevCaster : caster, .frame = uint32_t(info.frame)});
        state.prevCaster = caster;
        state.havePrev = true;
    };
    d.outputs = [](demo::App&) {
        demo::Outputs o{.color = state.renderer.color(state.variant)};
        if (state.variant == Variant::Amortized) {
            state.renderer.cache().visualize(state.visualization);
            o.visualization = state.visualization.id();
        }
        return o;
    };
    d.stats = [](demo::App&) {
        demo::Stats s{{"taps", double(state.settings.taps)}, {"shadow_map_renders", double(state.renderer.shadowMapRenders())}};
        if (state.variant == Variant::Amortized) {
            s["hit_rate"] = state.renderer.cache().stats().hitRate();
            s["lambda"] = state.settings.lambda;
        }
        return s;
    };
    d.gui = [](demo::App&) {
        ImGui::SliderInt("taps (k)", &state.settings.taps, 1, 64);
        ImGui::SliderFloat("lambda", &state.settings.lambda, 0.0f, 0.95f);
        ImGui::SliderFloat("radius (m)", &state.settings.radius, 0.02f, 1.0f);
        ImGui::Checkbox("depth-aware blur", &state.settings.blur);
        int remap = static_cast<int>(state.settings.remap);
        ImGui::Combo("remap", &remap, "none\0smoothstep\0threshold\0");
        state.settings.remap = static_cast<Remap>(remap);
        ImGui::Text("M: PCF / amortized (now %s)", variantName(state.variant));
    };
    d.cleanup = [](demo::App&) { state = {}; };
    return d;
}

} // namespace

int main(int argc, char** argv) { return demo::runDemo(argc, argv, shadowsDemo()); }
