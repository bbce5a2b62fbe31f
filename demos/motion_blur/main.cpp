// rrc-motion-blur: motion blur by accumulation with the reprojection cache (chapter section 6.5.2).
// Each frame averages N time samples across the shutter: the skinned character running down the
// temple aisle, the camera tracking it. --mode brute renders every sample in full; cached renders
// the first in full and every later one through the previous sample's cache. N is live in a window.
#include "shutter.hpp"

#include "accumulation/demo_hooks.hpp"
#include "support/flow_option.hpp"
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
    bool neverCacheCharacter = false;
    std::string flow = "one-pass";   // measured fastest on llvmpipe (docs/motion_blur.md)
    std::string characterPath = "assets/character.glb";
    motion_blur::Shot shot;
    demo::DrawScene scene;
    accumulation::Character character;
} state;

void renderFrame(double time) {
    const accumulation::SceneRef scene{.statics = state.scene.draws, .character = &state.character,
                                       .characterNeverCached = state.neverCacheCharacter};
    const glm::dmat4 projection = perspectiveReversedZ(0.9, double(state.renderer.cache().width()) / state.renderer.cache().height(), 0.1);
    state.renderer.render(state.variant, scene, state.samples, [&](int i, int n) {
        const double t = motion_blur::sampleTime(state.shot, time, i, n);
        state.character.pose(t, motion_blur::characterPlacement(state.shot, t));
        return accumulation::SampleView{motion_blur::cameraView(state.shot, t), projection};
    });
}

demo::DemoDesc motionBlurDemo() {
    demo::DemoDesc d;
    d.name = "motion_blur";
    d.addOptions = [](CLI::App& app) {
        app.add_option("--samples", state.samples, "time samples per frame (N)")->check(CLI::Range(1, 256));
        app.add_option("--shutter", state.shot.shutter, "seconds the shutter is open")->check(CLI::Range(0.0, 1.0));
        app.add_option("--octaves", state.octaves, "Perlin octaves of the marble")->check(CLI::Range(1, 12));
        app.add_option("--character", state.characterPath, "skinned glTF with a 'heroine' node and a 'run' clip");
        app.add_option("--flow", state.flow, "cached control flow")->check(CLI::IsMember(demo::kFlowNames));
        app.add_option("--refresh-period", state.refreshPeriod, "shade every 8x8 block afresh every this many samples (0: never)");
        app.add_flag("--no-stats", state.noStats, "no per-pixel outcome statistics (hit rate, hit/miss image)");
        app.add_flag("--never-cache-character", state.neverCacheCharacter,
                     "force misses on the character (as for an object whose look changes within the shutter)");
    };
    d.init = [](demo::App& app) -> Result<void> {
        auto scene = demo::loadDrawScene(app.scenePath().empty() ? "procedural" : app.scenePath());
        if (!scene) return scene.error();
        state.scene = std::move(scene).value();
        auto character = accumulation::Character::load(state.characterPath);
        if (!character) return character.error();
        state.character = std::move(character).value();
        app.shaders().add(demo::supportShaders());
        app.shaders().add(accumulation::shaders());
        return state.renderer.init(app.width(), app.height(), app.shaders(),
                                   {.octaves = state.octaves,
                                    .flow = demo::flowNamed(state.flow), .probe = demo::probeNamed(state.flow),
                                    .stats = !state.noStats,
                                    .refreshPeriod = state.refreshPeriod});
    };
    d.frame = [](demo::App& app, const demo::FrameInfo& info) {
        state.variant = app.mode() == demo::Mode::Brute ? Variant::Brute : Variant::Cached;
        renderFrame(info.time);
    };
    accumulation::addCommonHooks(d, state);
    d.gui = [](demo::App&) {
        ImGui::Begin("motion blur");
        ImGui::SliderInt("samples N", &state.samples, 1, 64);
        float shutterMs = float(state.shot.shutter * 1000.0);
        if (ImGui::SliderFloat("shutter ms", &shutterMs, 0.0f, 100.0f)) state.shot.shutter = shutterMs / 1000.0;
        ImGui::Checkbox("never cache the character", &state.neverCacheCharacter);
        ImGui::Text("%s (M toggles), V shows the last sample's hits", accumulation::variantName(state.variant));
        ImGui::End();
    };
    d.cleanup = [](demo::App&) { state = {}; };
    return d;
}

} // namespace

int main(int argc, char** argv) { return demo::runDemo(argc, argv, motionBlurDemo()); }
