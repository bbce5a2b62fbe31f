// rrc-validate-scene FILE...: loads each glTF/GLB with the scene loader's full validation and
// prints "OK <file>" or the error; exits 1 if any file fails (for scripts and CI).
#include "scene.hpp"

#include <cstdio>

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: rrc-validate-scene FILE...\n");
        return 2;
    }
    // The loader logs each failure; print it ourselves, once, on stdout next to the OK lines.
    rrc::setLogger([](const rrc::LogItem&) {});
    int failures = 0;
    for (int i = 1; i < argc; ++i) {
        auto scene = rrc::scene::loadScene(argv[i]);
        if (scene) {
            const auto& s = scene.value();
            std::printf("OK %s (%zu meshes, %zu nodes, %zu images, %zu skins, %zu animations)\n", argv[i], s.meshes.size(),
                        s.nodes.size(), s.images.size(), s.skins.size(), s.animations.size());
        } else {
            std::printf("FAIL [%s] %s\n", std::string(rrc::logIdName(scene.error().id)).c_str(), scene.error().message.c_str());
            ++failures;
        }
    }
    return failures ? 1 : 0;
}
