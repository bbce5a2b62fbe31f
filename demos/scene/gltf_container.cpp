// Reading the scene file and checking the GLB container layout (glTF 2.0 spec, "Binary glTF
// Layout"): 12-byte header, a JSON chunk, an optional BIN chunk, all inside the declared length.
#include "gltf_container.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstring>
#include <fstream>

namespace rrc::scene::detail {
namespace {

constexpr uint32_t kChunkJson = 0x4E4F534A;  // "JSON" little-endian
constexpr uint32_t kChunkBin = 0x004E4942;   // "BIN\0"

uint32_t readU32(const unsigned char* p) {
    return uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 | uint32_t(p[3]) << 24;
}

std::string printable(const unsigned char* p, size_t n) {
    std::string s;
    for (size_t i = 0; i < n; ++i) {
        if (std::isprint(p[i])) s += char(p[i]);
        else { char hex[8]; std::snprintf(hex, sizeof hex, "\\x%02x", p[i]); s += hex; }
    }
    return s;
}

bool hasGlbExtension(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext == ".glb";
}

Result<void> splitGlb(Container& c) {
    const auto& b = c.bytes;
    const size_t size = b.size();
    if (size < 12)
        return invalid("truncated GLB header: the file has " + std::to_string(size) + " bytes, the header needs 12");
    if (std::memcmp(b.data(), "glTF", 4) != 0)
        return invalid("bad GLB magic '" + printable(b.data(), 4) + "' (expected 'glTF')");
    if (const uint32_t version = readU32(&b[4]); version != 2)
        return invalid("GLB container version " + std::to_string(version) + " is not supported (must be 2)");
    const uint64_t length = readU32(&b[8]);
    if (length > size)
        return invalid("GLB is truncated: its header declares " + std::to_string(length) + " bytes, the file has " +
                       std::to_string(size));
    if (length < size)
        return invalid("GLB header declares " + std::to_string(length) + " bytes but the file has " +
                       std::to_string(size) + " (trailing data)");

    // Chunks: 8-byte header (length, type) then the payload; every bound checked in 64 bits.
    uint64_t offset = 12;
    for (int index = 0; offset < length; ++index) {
        const std::string name = "GLB chunk " + std::to_string(index);
        if (length - offset < 8)
            return invalid(name + ": its 8-byte chunk header runs past the end of the file");
        const uint64_t chunkLength = readU32(&b[offset]);
        const uint32_t type = readU32(&b[offset + 4]);
        const std::string typeName = name + " (" + printable(&b[offset + 4], 4) + ")";
        if (chunkLength > length - offset - 8)
            return invalid(typeName + " claims " + std::to_string(chunkLength) + " bytes but only " +
                           std::to_string(length - offset - 8) + " remain in the file");
        const unsigned char* payload = &b[offset + 8];
        if (index == 0) {
            if (type != kChunkJson) return invalid(typeName + ": the first chunk must be JSON");
            if (chunkLength == 0) return invalid(typeName + ": the JSON chunk is empty");
            c.json = std::string_view(reinterpret_cast<const char*>(payload), chunkLength);
        } else if (index == 1 && type == kChunkBin) {
            // tinygltf reads the BIN chunk only directly after JSON and rejects short or unaligned ones.
            if (chunkLength < 4 || chunkLength % 4 != 0)
                return invalid(typeName + ": BIN chunk length " + std::to_string(chunkLength) +
                               " is not a positive multiple of 4");
            c.binSize = chunkLength;
        } else if (type == kChunkBin) {
            return invalid(typeName + ": a BIN chunk must directly follow the JSON chunk");
        } else if (index == 1) {
            return invalid(typeName + ": unsupported chunk type after the JSON chunk (tinygltf expects BIN)");
        }
        offset += 8 + chunkLength;
    }
    if (c.json.empty()) return invalid("GLB has no JSON chunk");
    return {};
}

} // namespace

Result<std::vector<unsigned char>> readFileBounded(const std::filesystem::path& path, LoadContext& context,
                                                   const std::string& what) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
        return ioFailed(what + ": '" + path.string() + "' does not exist or is not a regular file");
    const uint64_t size = std::filesystem::file_size(path, ec);
    if (ec) return ioFailed(what + ": cannot read the size of '" + path.string() + "': " + ec.message());
    if (!context.charge(size, what)) return invalid(context.budgetError);
    std::ifstream in(path, std::ios::binary);
    std::vector<unsigned char> bytes(size);
    if (!in || !in.read(reinterpret_cast<char*>(bytes.data()), std::streamsize(size)))
        return ioFailed(what + ": cannot read '" + path.string() + "'");
    return bytes;
}

Result<Container> readContainer(const std::string& path, LoadContext& context) {
    auto bytes = readFileBounded(path, context, "the scene file");
    if (!bytes) return bytes.error();
    Container c;
    c.bytes = std::move(bytes).value();
    if (c.bytes.empty()) return invalid("the file is empty (0 bytes)");
    // tinygltf takes 32-bit lengths.
    if (c.bytes.size() > 0xFFFFFFFFu) return invalid("the file is larger than 4 GiB");
    c.glb = hasGlbExtension(path) || (c.bytes.size() >= 4 && std::memcmp(c.bytes.data(), "glTF", 4) == 0);
    if (c.glb) {
        if (auto r = splitGlb(c); !r) return r.error();
    } else {
        c.json = std::string_view(reinterpret_cast<const char*>(c.bytes.data()), c.bytes.size());
    }
    return c;
}

} // namespace rrc::scene::detail
