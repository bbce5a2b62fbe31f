// The JSON-level gate in front of tinygltf (see gltf_precheck.hpp for why each check is here).
#include "gltf_precheck.hpp"

#include "gltf_uri.hpp"

#include <nlohmann/json.hpp>

#include <array>
#include <climits>
#include <optional>

namespace rrc::scene::detail {
namespace {

using json = nlohmann::json;

constexpr int kMaxDepth = 64;  // tinygltf converts "extras" recursively: deep nesting would overflow the stack

// Properties whose value is an index into a top-level array, and arrays of such indices.
constexpr std::array<std::string_view, 16> kIndexKeys = {
    "scene", "node", "mesh", "skin", "camera", "material", "indices", "bufferView", "buffer",
    "source", "sampler", "index", "skeleton", "inverseBindMatrices", "input", "output"};
constexpr std::array<std::string_view, 3> kIndexArrays = {"children", "nodes", "joints"};

template <size_t N>
bool contains(const std::array<std::string_view, N>& set, std::string_view key) {
    for (auto k : set) if (k == key) return true;
    return false;
}

Result<void> checkDepth(std::string_view text) {
    int depth = 0;
    bool inString = false, escaped = false;
    for (char c : text) {
        if (inString) {
            if (escaped) escaped = false;
            else if (c == '\\') escaped = true;
            else if (c == '"') inString = false;
        } else if (c == '"') {
            inString = true;
        } else if (c == '[' || c == '{') {
            if (++depth > kMaxDepth) return invalid("JSON is nested deeper than " + std::to_string(kMaxDepth) + " levels");
        } else if (c == ']' || c == '}') {
            --depth;
        }
    }
    return {};
}

Result<json> parseJson(std::string_view text) {
    try {
        return json::parse(text.begin(), text.end());
    } catch (const json::out_of_range& e) {
        // nlohmann refuses numbers that overflow a double (e.g. 1e999, i.e. +Inf) with error 406.
        return invalid(std::string("a JSON number is not finite: ") + e.what());
    } catch (const json::exception& e) {
        // nlohmann quotes the last token read, which can be a megabyte-long data URI.
        std::string what = e.what();
        if (what.size() > 240) what = what.substr(0, 240) + "...";
        return invalid("invalid JSON: " + what);
    }
}

Result<void> checkIndex(const json& value, const std::string& where) {
    if (value.is_number_unsigned() && value.get<uint64_t>() <= uint64_t(INT_MAX)) return {};
    return invalid(where + ": invalid index " + value.dump() + " (indices are integers from 0 to 2^31-1)");
}

// Every index-valued property outside "extras" and "extensions" must be a valid integer.
Result<void> checkIndices(const json& value, const std::string& where) {
    if (value.is_array()) {
        for (size_t i = 0; i < value.size(); ++i)
            if (auto r = checkIndices(value[i], where + "[" + std::to_string(i) + "]"); !r) return r;
        return {};
    }
    if (!value.is_object()) return {};
    for (const auto& [key, item] : value.items()) {
        if (key == "extras" || key == "extensions") continue;
        const std::string path = where.empty() ? key : where + "." + key;
        if (contains(kIndexKeys, key) && !item.is_structured()) {
            if (auto r = checkIndex(item, path); !r) return r;
        } else if (key == "attributes" && item.is_object()) {
            for (const auto& [name, index] : item.items())
                if (auto r = checkIndex(index, path + "." + name); !r) return r;
        } else if (key == "targets" && item.is_array()) {
            for (size_t t = 0; t < item.size(); ++t) {
                if (!item[t].is_object()) return invalid(path + "[" + std::to_string(t) + "] is not an object");
                for (const auto& [name, index] : item[t].items())
                    if (auto r = checkIndex(index, path + "[" + std::to_string(t) + "]." + name); !r) return r;
            }
        } else if (contains(kIndexArrays, key) && item.is_array()) {
            for (size_t i = 0; i < item.size(); ++i) {
                const std::string at = path + "[" + std::to_string(i) + "]";
                if (auto r = item[i].is_structured() ? checkIndices(item[i], at) : checkIndex(item[i], at); !r) return r;
            }
        } else if (auto r = checkIndices(item, path); !r) {
            return r;
        }
    }
    return {};
}

const json& arrayMember(const json& object, const char* key) {
    static const json empty = json::array();
    const auto it = object.find(key);
    return it != object.end() && it->is_array() ? *it : empty;
}

// An optional non-negative integer property (absent: `fallback`).
Result<uint64_t> unsignedMember(const json& object, const char* key, const std::string& where,
                                std::optional<uint64_t> fallback) {
    const auto it = object.find(key);
    if (it == object.end()) {
        if (fallback) return *fallback;
        return invalid(where + ": '" + key + "' is missing");
    }
    if (!it->is_number_unsigned()) return invalid(where + ": '" + key + "' must be a non-negative integer, not " + it->dump());
    return it->get<uint64_t>();
}

std::string count(size_t n, const char* what) { return std::to_string(n) + " " + what; }

Result<void> checkVersion(const json& root) {
    const auto asset = root.find("asset");
    if (asset == root.end() || !asset->is_object()) return invalid("'asset' is missing or not an object");
    const auto version = asset->find("version");
    if (version == asset->end() || !version->is_string()) return invalid("asset.version is missing");
    const std::string v = version->get<std::string>();
    if (v.substr(0, 2) != "2.") return invalid("glTF version '" + v + "' is not supported (need 2.x)");
    if (const auto min = asset->find("minVersion"); min != asset->end() && min->is_string() && min->get<std::string>() > "2.0")
        return invalid("asset.minVersion '" + min->get<std::string>() + "' is newer than this loader (2.0)");
    // This loader implements no extension, so content that requires one cannot be shown correctly.
    if (const auto required = root.find("extensionsRequired"); required != root.end() && required->is_array() && !required->empty())
        return invalid("required extension " + (*required)[0].dump() + " is not supported");
    return {};
}

// Declared buffer lengths; tinygltf makes each loaded buffer exactly this long.
Result<std::vector<uint64_t>> checkBuffers(const json& root, const Container& container, LoadContext& context) {
    std::vector<uint64_t> lengths;
    const json& buffers = arrayMember(root, "buffers");
    for (size_t i = 0; i < buffers.size(); ++i) {
        const std::string what = "buffer " + std::to_string(i);
        if (!buffers[i].is_object()) return invalid(what + " is not an object");
        auto length = unsignedMember(buffers[i], "byteLength", what, std::nullopt);
        if (!length) return length.error();
        if (length.value() == 0) return invalid(what + ": byteLength must be at least 1");
        const auto uri = buffers[i].find("uri");
        if (uri == buffers[i].end()) {
            if (!container.glb || i != 0) return invalid(what + " has no uri (only a GLB's first buffer may omit it)");
            if (container.binSize == 0) return invalid(what + " refers to the GLB BIN chunk, but the GLB has none");
            if (length.value() > container.binSize)
                return invalid(what + ": byteLength " + std::to_string(length.value()) + " exceeds the GLB BIN chunk (" +
                               std::to_string(container.binSize) + " bytes)");
        } else if (!uri->is_string()) {
            return invalid(what + ": uri is not a string");
        } else if (const std::string text = uri->get<std::string>(); isDataUri(text)) {
            auto size = checkDataUri(text, what);
            if (!size) return size.error();
            if (size.value() != length.value())
                return invalid(what + ": data URI holds " + std::to_string(size.value()) + " bytes, byteLength says " +
                               std::to_string(length.value()));
            if (!context.charge(2 * size.value(), what + " (decoded data URI)")) return invalid(context.budgetError);
        } else {
            auto path = resolveFileUri(text, context, what);
            if (!path) return path.error();
            std::error_code ec;
            const uint64_t size = std::filesystem::file_size(path.value(), ec);
            // tinygltf insists on an exact match; say so here rather than through its message.
            if (ec || size != length.value())
                return invalid(what + ": file '" + text + "' has " + std::to_string(size) + " bytes, byteLength says " +
                               std::to_string(length.value()));
        }
        lengths.push_back(length.value());
    }
    return lengths;
}

Result<void> checkBufferViews(const json& root, LoadContext& context) {
    const std::vector<uint64_t>& bufferLengths = context.bufferLengths;
    const json& views = arrayMember(root, "bufferViews");
    for (size_t i = 0; i < views.size(); ++i) {
        const std::string what = "bufferView " + std::to_string(i);
        if (!views[i].is_object()) return invalid(what + " is not an object");
        auto buffer = unsignedMember(views[i], "buffer", what, std::nullopt);
        auto offset = unsignedMember(views[i], "byteOffset", what, 0);
        auto length = unsignedMember(views[i], "byteLength", what, std::nullopt);
        for (auto* r : {&buffer, &offset, &length}) if (!*r) return r->error();
        if (buffer.value() >= bufferLengths.size())
            return invalid(what + ": buffer " + std::to_string(buffer.value()) + " does not exist (" +
                           count(bufferLengths.size(), "buffers") + ")");
        if (length.value() == 0) return invalid(what + ": byteLength must be at least 1");
        const uint64_t available = bufferLengths[buffer.value()];
        uint64_t end = 0;
        if (!mulAdd(1, offset.value(), length.value(), end) || end > available)
            return invalid(what + ": bytes [" + std::to_string(offset.value()) + ", " + std::to_string(offset.value()) + " + " +
                           std::to_string(length.value()) + ") run past the end of buffer " + std::to_string(buffer.value()) +
                           " (" + std::to_string(available) + " bytes)");
        if (const auto stride = views[i].find("byteStride"); stride != views[i].end()) {
            if (!stride->is_number_unsigned() || stride->get<uint64_t>() < 4 || stride->get<uint64_t>() > 252 ||
                stride->get<uint64_t>() % 4 != 0)
                return invalid(what + ": byteStride " + stride->dump() + " must be a multiple of 4 in 4..252");
        }
        context.views.push_back({buffer.value(), offset.value(), length.value()});
    }
    return {};
}

Result<void> checkImages(const json& root, LoadContext& context) {
    const json& images = arrayMember(root, "images");
    const size_t viewCount = arrayMember(root, "bufferViews").size();
    for (size_t i = 0; i < images.size(); ++i) {
        const std::string what = "image " + std::to_string(i);
        if (!images[i].is_object()) return invalid(what + " is not an object");
        const auto uri = images[i].find("uri");
        const auto view = images[i].find("bufferView");
        if ((uri == images[i].end()) == (view == images[i].end()))
            return invalid(what + ": needs exactly one of 'uri' and 'bufferView'");
        if (view != images[i].end()) {
            // Checked here because tinygltf hands the decoder a pointer into this bufferView unchecked.
            if (!view->is_number_unsigned() || view->get<uint64_t>() >= viewCount)
                return invalid(what + ": bufferView " + view->dump() + " does not exist (" + count(viewCount, "bufferViews") + ")");
            if (!images[i].contains("mimeType")) return invalid(what + ": an image in a bufferView needs a mimeType");
        } else if (!uri->is_string()) {
            return invalid(what + ": uri is not a string");
        } else if (const std::string text = uri->get<std::string>(); isDataUri(text)) {
            auto size = checkDataUri(text, what);
            if (!size) return size.error();
            if (!context.charge(2 * size.value(), what + " (decoded data URI)")) return invalid(context.budgetError);
        } else if (auto path = resolveFileUri(text, context, what); !path) {
            return path.error();
        }
    }
    return {};
}

// tinygltf dereferences each primitive's index accessor and its bufferView while parsing.
Result<void> checkIndexAccessors(const json& root) {
    const json& accessors = arrayMember(root, "accessors");
    const size_t viewCount = arrayMember(root, "bufferViews").size();
    const json& meshes = arrayMember(root, "meshes");
    for (size_t m = 0; m < meshes.size(); ++m) {
        if (!meshes[m].is_object()) return invalid("mesh " + std::to_string(m) + " is not an object");
        const json& primitives = arrayMember(meshes[m], "primitives");
        for (size_t p = 0; p < primitives.size(); ++p) {
            const std::string what = "mesh " + std::to_string(m) + " primitive " + std::to_string(p);
            if (!primitives[p].is_object()) return invalid(what + " is not an object");
            const auto indices = primitives[p].find("indices");
            if (indices == primitives[p].end()) continue;
            if (!indices->is_number_unsigned()) return invalid(what + ": indices must be an accessor index");
            const uint64_t a = indices->get<uint64_t>();
            if (a >= accessors.size())
                return invalid(what + ": indices accessor " + std::to_string(a) + " does not exist (" +
                               count(accessors.size(), "accessors") + ")");
            const auto view = accessors[a].is_object() ? accessors[a].find("bufferView") : accessors[a].end();
            if (!accessors[a].is_object() || view == accessors[a].end())
                return invalid("accessor " + std::to_string(a) + " (indices of " + what + ") has no bufferView");
            if (!view->is_number_unsigned() || view->get<uint64_t>() >= viewCount)
                return invalid("accessor " + std::to_string(a) + " (indices of " + what + "): bufferView " +
                               view->dump() + " does not exist (" + count(viewCount, "bufferViews") + ")");
        }
    }
    return {};
}

} // namespace

Result<void> precheckJson(const Container& container, LoadContext& context) try {
    if (container.json.size() > context.options.maxJsonBytes)
        return invalid("the JSON is " + std::to_string(container.json.size()) + " bytes, over the limit of " +
                       std::to_string(context.options.maxJsonBytes));
    if (auto r = checkDepth(container.json); !r) return r;
    auto parsed = parseJson(container.json);
    if (!parsed) return parsed.error();
    const json& root = parsed.value();
    if (!root.is_object()) return invalid("the JSON root is not an object");
    if (auto r = checkVersion(root); !r) return r;
    for (const char* key : {"accessors", "animations", "buffers", "bufferViews", "cameras", "images", "materials",
                            "meshes", "nodes", "samplers", "scenes", "skins", "textures"})
        if (root.contains(key) && !root[key].is_array()) return invalid(std::string("'") + key + "' must be an array");
    if (auto r = checkIndices(root, ""); !r) return r;
    auto lengths = checkBuffers(root, container, context);
    if (!lengths) return lengths.error();
    context.bufferLengths = std::move(lengths).value();
    if (auto r = checkBufferViews(root, context); !r) return r;
    if (auto r = checkImages(root, context); !r) return r;
    return checkIndexAccessors(root);
} catch (const std::exception& e) {
    // A value of an unexpected JSON type that a check above did not anticipate.
    return invalid(std::string("malformed glTF JSON: ") + e.what());
}

} // namespace rrc::scene::detail
