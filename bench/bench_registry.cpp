// The registry behind DemoRegistration: a function-local static, so registrations from other
// translation units' static initialisers never meet an unconstructed vector.
#include "bench_scenes.hpp"

#include <algorithm>
#include <cstdio>

namespace rrc::bench {
namespace {
std::vector<DemoEntry>& registry() {
    static std::vector<DemoEntry> entries;
    return entries;
}
} // namespace

const std::vector<DemoEntry>& registeredDemos() {
    auto& entries = registry();
    std::stable_sort(entries.begin(), entries.end(), [](const DemoEntry& a, const DemoEntry& b) { return a.order < b.order; });
    return entries;
}

DemoRegistration::DemoRegistration(std::string name, int order, DemoRunner run) {
    registry().push_back({std::move(name), order, std::move(run)});
}

std::optional<BenchScene> loadBenchScene(const std::string& path) {
    auto scene = demo::loadDrawScene(path);
    if (!scene) {
        std::fprintf(stderr, "rrc-bench: cannot load scene %s\n", path.c_str());
        return std::nullopt;
    }
    return std::move(scene).value();
}

} // namespace rrc::bench
