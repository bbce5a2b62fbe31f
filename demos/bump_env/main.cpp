// rrc-bump-env: a bump-mapped sphere reflecting the sky cube map (chapter section 6.5.4), with
// k = n x n sub-pixel samples per pixel and frame. --mode brute: the k-sample average alone;
// --mode cached: the same k samples amortized through the reprojection cache (--lambda 0.6).
#include "bump_env_renderer.hpp"
#include "bump_env_scene.hpp"

#include "common/app.hpp"

#include <CLI/CLI.hpp>
#include <cmath>
#include <imgui.h>

namespace rrc::bump_env {
std::span<const EmbeddedFile> shaders();
}

namespace {

using namespace rrc;
using namespace rrc::bump_env;

struct State {
    BumpSettings settings;
    int samples = 4;
    std::string assets = "assets";
    BumpEnvRenderer renderer;
    Texture visualization;
    Variant variant = Variant::Amortized;
} state;

demo::DemoDesc bumpEnvDemo() {
    demo::DemoDesc d;
    d.name = "bump_env";
    d.addOptions = [](CLI::App& app) {
        app.add_option("--samples", state.samples, "samples per pixel and frame (k, a square)")
            ->check(CLI::IsMember({1, 4, 9, 16, 25, 36, 49, 64, 256}));
        app.add_option("--lambda", state.settings.lambda, "recursive filter weight")->check(CLI::Range(0.0, 0.99));
        app.add_option("--bump-strength", state.settings.bumpStrength, "bump slope scale")->check(CLI::NonNegativeNumber);
        app.add_option("--assets", state.assets, "folder with bump.png and env/")->check(CLI::ExistingDirectory);
    };
    d.init = [](demo::App& app) -> Result<void> {
        state.settings.grid = static_cast<int>(std::lround(std::sqrt(double(state.samples))));
        state.settings.seed = app.seed();
        app.shaders().add(bump_env::shaders());
        app.setCameraPath(cameraOrbit());
        return state.renderer.init(app.width(), app.height(), app.shaders(), state.assets);
    };
    d.onResize = [](demo::App& app, int w, int h) { return state.renderer.init(w, h, app.shaders(), state.assets); };
    d.frame = [](demo::App& app, const demo::FrameInfo& info) {
        state.variant = app.mode() == demo::Mode::Brute ? Variant::Brute : Variant::Amortized;
        state.renderer.render(state.variant, state.settings,
                              {.view = app.camera().view(), .projection = app.camera().projection(app.aspect()),
                               .frame = uint32_t(info.frame)});
    };
    d.outputs = [](demo::App&) {
        demo::Outputs o{.color = state.renderer.color()};
        if (state.variant == Variant::Amortized) {
            state.renderer.cache().visualize(state.visualization);
            o.visualization = state.visualization.id();
        }
        return o;
    };
    d.stats = [](demo::App&) {
        demo::Stats s{{"samples", double(state.settings.grid * state.settings.grid)}};
        if (state.variant == Variant::Amortized) {
            s["hit_rate"] = state.renderer.cache().stats().hitRate();
            s["lambda"] = state.settings.lambda;
        }
        return s;
    };
    d.gui = [](demo::App&) {
        ImGui::SliderInt("grid n (k = n x n)", &state.settings.grid, 1, 16);
        ImGui::SliderFloat("lambda", &state.settings.lambda, 0.0f, 0.95f);
        ImGui::SliderFloat("bump strength", &state.settings.bumpStrength, 0.0f, 20.0f);
        ImGui::Text("k = %d; M: brute / amortized (now %s)", state.settings.grid * state.settings.grid, variantName(state.variant));
    };
    d.cleanup = [](demo::App&) { state = {}; };
    return d;
}

} // namespace

int main(int argc, char** argv) { return demo::runDemo(argc, argv, bumpEnvDemo()); }
