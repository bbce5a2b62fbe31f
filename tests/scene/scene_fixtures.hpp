// Test fixtures for the scene loader that need no generator: a one-triangle glTF document built
// in code (the same triangle as scripts/make_bad_gltf.py), helpers that append accessors with
// their own data-URI buffers, and a temporary folder the documents are written into.
#pragma once
#include <nlohmann/json.hpp>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <unistd.h>

namespace rrc::test {

inline std::string base64(const void* data, size_t size) {
    static const char* alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    const auto* b = static_cast<const unsigned char*>(data);
    std::string out;
    for (size_t i = 0; i < size; i += 3) {
        const uint32_t n = uint32_t(b[i]) << 16 | (i + 1 < size ? uint32_t(b[i + 1]) << 8 : 0) | (i + 2 < size ? b[i + 2] : 0);
        out += alphabet[n >> 18 & 63];
        out += alphabet[n >> 12 & 63];
        out += i + 1 < size ? alphabet[n >> 6 & 63] : '=';
        out += i + 2 < size ? alphabet[n & 63] : '=';
    }
    return out;
}

inline std::string dataUri(const std::vector<unsigned char>& bytes) {
    return "data:application/octet-stream;base64," + base64(bytes.data(), bytes.size());
}

template <class T>
std::vector<unsigned char> bytesOf(const std::vector<T>& values) {
    std::vector<unsigned char> out(values.size() * sizeof(T));
    if (!out.empty()) std::memcpy(out.data(), values.data(), out.size());
    return out;
}

// Appends a buffer (data URI), a bufferView and an accessor holding `values`; returns the accessor.
template <class T>
int addAccessor(nlohmann::json& doc, const std::vector<T>& values, int componentType, const char* type, size_t count,
                bool normalized = false) {
    const auto bytes = bytesOf(values);
    doc["buffers"].push_back({{"byteLength", bytes.size()}, {"uri", dataUri(bytes)}});
    doc["bufferViews"].push_back({{"buffer", doc["buffers"].size() - 1}, {"byteLength", bytes.size()}});
    nlohmann::json accessor = {{"bufferView", doc["bufferViews"].size() - 1}, {"componentType", componentType},
                               {"count", count}, {"type", type}};
    if (normalized) accessor["normalized"] = true;
    doc["accessors"].push_back(accessor);
    return int(doc["accessors"].size() - 1);
}

constexpr int kFloat = 5126, kUShort = 5123, kUByte = 5121;

// One red triangle (0,0,0), (1,0,0), (0,1,0) with normals and uvs, u16 indices, in node 0 of scene 0.
inline nlohmann::json triangleDocument() {
    nlohmann::json doc = {{"asset", {{"version", "2.0"}}}, {"scene", 0}, {"scenes", {{{"nodes", {0}}}}},
                          {"nodes", {{{"name", "triangle"}, {"mesh", 0}}}},
                          {"materials", {{{"name", "red"}, {"pbrMetallicRoughness", {{"baseColorFactor", {0.8, 0.1, 0.1, 1.0}}}}}}},
                          {"buffers", nlohmann::json::array()}, {"bufferViews", nlohmann::json::array()},
                          {"accessors", nlohmann::json::array()}};
    const int position = addAccessor(doc, std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0}, kFloat, "VEC3", 3);
    const int normal = addAccessor(doc, std::vector<float>{0, 0, 1, 0, 0, 1, 0, 0, 1}, kFloat, "VEC3", 3);
    const int uv = addAccessor(doc, std::vector<float>{0, 1, 1, 1, 0, 0}, kFloat, "VEC2", 3);
    const int indices = addAccessor(doc, std::vector<uint16_t>{0, 1, 2}, kUShort, "SCALAR", 3);
    const nlohmann::json primitive = {{"attributes", {{"POSITION", position}, {"NORMAL", normal}, {"TEXCOORD_0", uv}}},
                                      {"indices", indices}, {"material", 0}};
    doc["meshes"] = nlohmann::json::array({nlohmann::json{{"primitives", nlohmann::json::array({primitive})}}});
    return doc;
}

// A fresh folder under the system temp folder, removed with everything in it on destruction.
class TempDir {
public:
    TempDir() {
        static int counter = 0;
        path_ = std::filesystem::temp_directory_path() /
                ("rrc_scene_test_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
        std::filesystem::remove_all(path_);
        std::filesystem::create_directories(path_);
    }
    ~TempDir() {
        std::error_code ec;
        std::filesystem::remove_all(path_, ec);
    }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;

    const std::filesystem::path& path() const { return path_; }

    std::string write(const std::string& name, const std::string& text) const {
        const auto file = path_ / name;
        std::filesystem::create_directories(file.parent_path());
        std::ofstream(file, std::ios::binary) << text;
        return file.string();
    }
    std::string write(const std::string& name, const nlohmann::json& doc) const { return write(name, doc.dump(1)); }
    std::string write(const std::string& name, const std::vector<unsigned char>& bytes) const {
        return write(name, std::string(bytes.begin(), bytes.end()));
    }

private:
    std::filesystem::path path_;
};

} // namespace rrc::test
