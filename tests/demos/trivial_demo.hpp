// A trivial demo on the app skeleton, for tests: procedural marble (or wood) with Blinn-Phong on
// a full-screen triangle into an RGBA16F target, seen through the app's camera, plus an RGBA8
// "visualisation" target. A probe lets tests count callbacks and hook into frames.
#pragma once
#include <common/app.hpp>

#include <functional>
#include <utility>
#include <vector>

namespace rrc::demo::test {

struct Probe {
    int inits = 0, frames = 0, guiCalls = 0, cleanups = 0;
    std::vector<std::pair<int, int>> resizes;
    std::function<void(App&, const FrameInfo&)> onFrame;   // runs after the demo's frame
    bool failInit = false;
};

// Options: --octaves N (1..12, default 5), --material marble|wood. Orbit camera path.
DemoDesc trivialDemo(Probe* probe = nullptr);

} // namespace rrc::demo::test
