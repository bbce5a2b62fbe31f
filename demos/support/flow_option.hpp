// The --flow option of rrc-bench and rrc-motion-blur: a cached control flow by name, so both
// accept the same names and map them the same way.
#pragma once
#include <rrc/cache.hpp>

#include <string>
#include <string_view>
#include <vector>

namespace rrc::demo {

inline const std::vector<std::string> kFlowNames{"one-pass", "two-pass", "two-pass-no-probe"};

inline ControlFlow flowNamed(std::string_view name) { return name == "one-pass" ? ControlFlow::OnePass : ControlFlow::TwoPass; }

// FrameDesc::skipEmptyMissPass: only plain "two-pass" probes.
inline bool probeNamed(std::string_view name) { return name == "two-pass"; }

} // namespace rrc::demo
