// What the motion-blur and depth-of-field mains share: the renderer with its variant, N and the
// hit visualisation, and the DemoDesc hooks that need nothing else (resize, outputs, stats).
// Header-only: it needs demos/common's App, which the rrc-bench build of this folder does not link.
#pragma once

#include "accumulation/accumulation_renderer.hpp"
#include "common/app.hpp"

namespace rrc::accumulation {

struct DemoState {
    int samples = 8;
    int octaves = 8;
    uint32_t refreshPeriod = 4;   // --refresh-period
    bool noStats = false;         // no outcome target: no hit rate, no hit/miss image
    AccumulationRenderer renderer;
    Texture visualization;
    Variant variant = Variant::Cached;
};

// Sets d.onResize, d.outputs (the average; cached: the last sample's hits) and d.stats (N, hit
// rate). `state` must outlive the run.
inline void addCommonHooks(demo::DemoDesc& d, DemoState& state) {
    d.onResize = [&state](demo::App& app, int width, int height) {
        return state.renderer.init(width, height, app.shaders(), state.renderer.settings());
    };
    d.outputs = [&state](demo::App&) {
        demo::Outputs o{.color = state.renderer.result()};
        if (state.variant == Variant::Cached && !state.noStats) {
            state.renderer.cache().visualize(state.visualization);
            o.visualization = state.visualization.id();
        }
        return o;
    };
    d.stats = [&state](demo::App&) {
        demo::Stats s{{"samples", double(state.samples)}};
        if (state.variant == Variant::Cached) s["hit_rate"] = state.renderer.cache().stats().hitRate();
        return s;
    };
}

} // namespace rrc::accumulation
