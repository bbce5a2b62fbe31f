// rrc-stereo: anaglyph stereo with the reprojection cache (chapter section 6.5.1). The right eye
// is shaded in full into the cache; the left eye reuses it per pixel (hit: copy, miss: shade);
// red comes from the left eye, green and blue from the right. --mode brute shades both eyes.
// --view-dependent caches only the view-independent part and adds this eye's highlight.
#include "stereo_renderer.hpp"

#include "common/app.hpp"
#include "support/scene_draws.hpp"
#include "support/timing.hpp"

#include <CLI/CLI.hpp>

namespace rrc::stereo {
std::span<const EmbeddedFile> shaders();
}

namespace {

using namespace rrc;

struct State {
    bool viewDependent = false;
    double separation = 0.065;
    int octaves = 5;
    demo::DrawScene scene;
    stereo::StereoRenderer renderer;
    Texture visualization;
    stereo::Variant variant = stereo::Variant::Cached;
} state;

demo::DemoDesc stereoDemo() {
    demo::DemoDesc d;
    d.name = "stereo";
    d.addOptions = [](CLI::App& app) {
        app.add_flag("--view-dependent", state.viewDependent, "cache the view-independent part, add the highlight per eye");
        app.add_option("--eye-separation", state.separation, "distance between the eyes, scene units")->check(CLI::PositiveNumber);
        app.add_option("--octaves", state.octaves, "Perlin octaves of the marble")->check(CLI::Range(1, 12));
    };
    d.init = [](demo::App& app) -> Result<void> {
        auto scene = demo::loadDrawScene(app.scenePath().empty() ? "assets/temple.glb" : app.scenePath());
        if (!scene) return scene.error();
        state.scene = std::move(scene).value();
        app.shaders().add(demo::supportShaders());
        app.shaders().add(stereo::shaders());
        if (auto r = state.renderer.init(app.width(), app.height(), app.shaders(), state.octaves); !r) return r;
        app.setCameraPath(demo::FlyPath::colonnade({state.scene.boundsMin, state.scene.boundsMax}));
        return {};
    };
    d.onResize = [](demo::App& app, int width, int height) {
        return state.renderer.init(width, height, app.shaders(), state.octaves);
    };
    d.frame = [](demo::App& app, const demo::FrameInfo&) {
        state.variant = app.mode() == demo::Mode::Brute ? stereo::Variant::Brute
                        : state.viewDependent          ? stereo::Variant::CachedViewDependent
                                                       : stereo::Variant::Cached;
        const auto eyes = stereo::eyeViews(app.camera().view(), app.camera().projection(app.aspect()), state.separation);
        state.renderer.render(state.variant, eyes, state.scene.draws);
    };
    d.outputs = [](demo::App&) {
        demo::Outputs o{.color = state.renderer.anaglyph()};
        if (state.variant != stereo::Variant::Brute) {
            state.renderer.cache(state.variant).visualize(state.visualization);
            o.visualization = state.visualization.id();
        }
        return o;
    };
    d.stats = [](demo::App&) {
        demo::Stats s;
        if (state.variant != stereo::Variant::Brute) s["hit_rate"] = state.renderer.cache(state.variant).stats().hitRate();
        return s;
    };
    d.cleanup = [](demo::App&) { state = {}; };
    return d;
}

} // namespace

int main(int argc, char** argv) { return demo::runDemo(argc, argv, stereoDemo()); }
