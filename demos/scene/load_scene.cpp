// loadScene(): container and JSON pre-checks, tinygltf parsing (confined file access, checked
// image decoding), model validation, conversion. Errors are logged once, prefixed with the path.
#include "gltf_container.hpp"
#include "gltf_convert.hpp"
#include "gltf_image.hpp"
#include "gltf_precheck.hpp"
#include "gltf_uri.hpp"
#include "gltf_validate.hpp"

namespace rrc::scene {
namespace {

using namespace detail;

std::string trimmed(std::string text) {
    while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
    return text;
}

Result<tinygltf::Model> parse(const Container& container, LoadContext& context) {
    tinygltf::TinyGLTF loader;
    loader.SetFsCallbacks(fsCallbacks(context));
    loader.SetImageLoader(&loadImageData, &context);
    tinygltf::Model model;
    std::string err, warn;
    bool ok = false;
    try {
        const std::string folder = context.folder.string();
        ok = container.glb ? loader.LoadBinaryFromMemory(&model, &err, &warn, container.bytes.data(),
                                                         unsigned(container.bytes.size()), folder)
                           : loader.LoadASCIIFromString(&model, &err, &warn, container.json.data(),
                                                        unsigned(container.json.size()), folder);
    } catch (const std::exception& e) {  // tinygltf may throw from allocation or JSON access
        return invalid(std::string("tinygltf failed: ") + e.what());
    }
    if (!ok) {
        if (!context.budgetError.empty()) return invalid(context.budgetError);
        return invalid("tinygltf: " + trimmed(err.empty() ? "parsing failed" : err));
    }
    return model;
}

Result<Scene> load(const std::string& path, const LoadOptions& options) {
    LoadContext context{.options = options};
    std::error_code ec;
    context.folder = std::filesystem::canonical(std::filesystem::absolute(path).parent_path(), ec);
    if (ec) return ioFailed("cannot open the folder of the file: " + ec.message());
    auto container = readContainer(path, context);
    if (!container) return container.error();
    if (auto r = precheckJson(container.value(), context); !r) return r.error();
    auto parsed = parse(container.value(), context);
    if (!parsed) return parsed.error();
    tinygltf::Model& model = parsed.value();
    if (auto r = validateModel(model); !r) return r.error();

    Scene scene;
    scene.source = path;
    if (auto r = convertMeshes(model, scene, context); !r) return r.error();
    convertMaterials(model, scene);
    convertNodes(model, scene);
    if (auto r = convertSkins(model, scene, context); !r) return r.error();
    if (auto r = convertAnimations(model, scene, context); !r) return r.error();
    if (auto r = checkSkinnedMeshes(scene); !r) return r.error();
    return scene;
}

} // namespace

Result<Scene> loadScene(const std::string& path, const LoadOptions& options) {
    auto scene = load(path, options);
    if (!scene) return fail(scene.error().id, path + ": " + scene.error().message);
    return scene;
}

} // namespace rrc::scene
