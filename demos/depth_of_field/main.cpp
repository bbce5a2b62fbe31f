// rrc-depth-of-field: depth of field by accumulation with the reprojection cache (chapter section
// 6.5.3). Each frame averages N views from Poisson-disk points on the lens aperture, all focused on
// one plane, visited in nearest-neighbour order. --mode brute renders every view in full; cached
// renders the first in full and every later one through the previous view's cache. N is live.
#include "lens.hpp"

#include "accumulation/demo_hooks.hpp"
#include "support/scene_draws.hpp"
#include "support/timing.hpp"

#include <CLI/CLI.hpp>
#include <imgui.h>

namespace rrc::accumulation {
std::span<const EmbeddedFile> shaders();
}

namespace {

using namespace rrc;
using accumulation::Variant;

struct State : accumulation::DemoState {
    float aperture = 0.12f;   // lens radius, metres
    float focus = 9.0f;       // distance of the focal plane, metres
    bool randomOrder = false;
    demo::DrawScene scene;
} state;

demo::DemoDesc depthOfFieldDemo() {
    demo::DemoDesc d;
    d.name = "depth_of_field";
    d.addOptions = [](CLI::App& app) {
        app.add_option("--samples", state.samples, "lens samples per frame (N)")->check(CLI::Range(1, 256));
        app.add_option("--aperture", state.aperture, "lens radius, metres")->check(CLI::Range(0.0, 2.0));
        app.add_option("--focus", state.focus, "focal distance, metres")->check(CLI::Range(0.1, 1000.0));
        app.add_option("--octaves", state.octaves, "Perlin octaves of the marble")->check(CLI::Range(1, 12));
        app.add_option("--refresh-period", state.refreshPeriod, "shade every 8x8 block afresh every this many samples (0: never)");
        app.add_flag("--random-order", state.randomOrder, "visit the lens samples in random order");
    };
    d.init = [](demo::App& app) -> Result<void> {
        auto scene = demo::loadDrawScene(app.scenePath().empty() ? "procedural" : app.scenePath());
        if (!scene) return scene.error();
        state.scene = std::move(scene).value();
        app.shaders().add(demo::supportShaders());
        app.shaders().add(accumulation::shaders());
        app.setCameraPath(demo::FlyPath::colonnade({state.scene.boundsMin, state.scene.boundsMax}));
        return state.renderer.init(app.width(), app.height(), app.shaders(),
                                   {.octaves = state.octaves, .refreshPeriod = state.refreshPeriod});
    };
    d.frame = [](demo::App& app, const demo::FrameInfo&) {
        state.variant = app.mode() == demo::Mode::Brute ? Variant::Brute : Variant::Cached;
        const auto lens = dof::ordered(dof::poissonDisk(state.samples, app.seed()),
                                       state.randomOrder ? dof::LensOrder::Random : dof::LensOrder::NearestNeighbour, app.seed());
        const glm::dmat4 view = app.camera().view(), projection = app.camera().projection(app.aspect());
        const accumulation::SceneRef scene{.statics = state.scene.draws, .moving = false};
        state.renderer.render(state.variant, scene, state.samples, [&](int i, int) {
            return accumulation::SampleView{dof::lensView(view, lens[size_t(i)] * double(state.aperture), state.focus), projection};
        });
    };
    accumulation::addCommonHooks(d, state);
    d.gui = [](demo::App&) {
        ImGui::Begin("depth of field");
        ImGui::SliderInt("samples N", &state.samples, 1, 64);
        ImGui::SliderFloat("aperture radius m", &state.aperture, 0.0f, 0.5f);
        ImGui::SliderFloat("focus m", &state.focus, 1.0f, 60.0f);
        ImGui::Checkbox("random lens order", &state.randomOrder);
        ImGui::Text("%s (M toggles), V shows the last view's hits", accumulation::variantName(state.variant));
        ImGui::End();
    };
    d.cleanup = [](demo::App&) { state = {}; };
    return d;
}

} // namespace

int main(int argc, char** argv) { return demo::runDemo(argc, argv, depthOfFieldDemo()); }
