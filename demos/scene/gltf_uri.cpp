// URI checks for buffers and images: data URIs decoded by tinygltf, and relative file paths that
// must stay inside the scene's folder (after percent-decoding and symlink resolution).
#include "gltf_container.hpp"
#include "gltf_uri.hpp"

#include <algorithm>
#include <array>
#include <cctype>

namespace rrc::scene::detail {
namespace {

// The media types tinygltf's IsDataURI() recognises; any other data URI it would treat as a path.
constexpr std::array<std::string_view, 7> kDataMediaTypes = {
    "application/octet-stream", "application/gltf-buffer", "image/jpeg", "image/png",
    "image/bmp", "image/gif", "text/plain"};

std::string shown(std::string_view uri) {
    constexpr size_t kMax = 80;  // data URIs can be megabytes long
    return "'" + std::string(uri.substr(0, kMax)) + (uri.size() > kMax ? "...'" : "'");
}

int hexValue(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return 0;  // as dlib::urldecode does, so we check exactly the path tinygltf would open
}

// tinygltf's dlib::urldecode: '+' becomes a space, "%xy" a byte.
std::string urlDecode(std::string_view s) {
    std::string out;
    for (size_t i = 0; i < s.size(); ++i) {
        if (s[i] == '+') out += ' ';
        else if (s[i] == '%' && s.size() > i + 2) { out += char(hexValue(s[i + 1]) << 4 | hexValue(s[i + 2])); i += 2; }
        else out += s[i];
    }
    return out;
}

bool hasScheme(std::string_view uri) {
    // RFC 3986: scheme = ALPHA *( ALPHA / DIGIT / "+" / "-" / "." ) ":"
    const size_t colon = uri.find(':');
    if (colon == std::string_view::npos || colon == 0 || !std::isalpha(static_cast<unsigned char>(uri[0]))) return false;
    return std::all_of(uri.begin(), uri.begin() + std::ptrdiff_t(colon), [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '+' || c == '-' || c == '.';
    });
}

bool insideFolder(const std::filesystem::path& folder, const std::filesystem::path& path) {
    std::error_code ec;
    const auto canonical = std::filesystem::weakly_canonical(path, ec);
    if (ec) return false;
    auto [f, p] = std::mismatch(folder.begin(), folder.end(), canonical.begin(), canonical.end());
    return f == folder.end();
}

bool fileExists(const std::string& path, void* user) {
    const auto& context = *static_cast<const LoadContext*>(user);
    std::error_code ec;
    return insideFolder(context.folder, path) && std::filesystem::is_regular_file(path, ec);
}

std::string expandFilePath(const std::string& path, void*) { return path; }

bool readWholeFile(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* user) {
    auto& context = *static_cast<LoadContext*>(user);
    if (!insideFolder(context.folder, path)) {
        if (err) *err += "refusing to read '" + path + "' outside the scene's folder";
        return false;
    }
    auto bytes = readFileBounded(path, context, "'" + path + "'");
    if (!bytes) {
        if (err) *err += bytes.error().message;
        return false;
    }
    *out = std::move(bytes).value();
    return true;
}

bool writeWholeFile(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
    if (err) *err += "the scene loader never writes files";
    return false;
}

} // namespace

Result<uint64_t> checkDataUri(std::string_view uri, const std::string& what) {
    const size_t comma = uri.find(',');
    if (comma == std::string_view::npos) return invalid(what + ": data URI has no ',' before its payload");
    const std::string_view header = uri.substr(5, comma - 5);
    constexpr std::string_view kBase64 = ";base64";
    if (header.size() < kBase64.size() || header.substr(header.size() - kBase64.size()) != kBase64)
        return invalid(what + ": data URI is not base64-encoded (';base64' missing)");
    const std::string_view media = header.substr(0, header.size() - kBase64.size());
    if (std::find(kDataMediaTypes.begin(), kDataMediaTypes.end(), media) == kDataMediaTypes.end())
        return invalid(what + ": data URI media type '" + std::string(media) + "' is not supported");

    // Strict base64: the alphabet, length a multiple of 4, at most two '=' and only at the end.
    // tinygltf's decoder skips nothing and stops silently at the first bad character.
    const std::string_view payload = uri.substr(comma + 1);
    if (payload.empty()) return invalid(what + ": data URI has an empty payload");
    if (payload.size() % 4 != 0)
        return invalid(what + ": data URI payload is not valid base64 (length " + std::to_string(payload.size()) +
                       " is not a multiple of 4)");
    size_t padding = 0;
    for (size_t i = 0; i < payload.size(); ++i) {
        const char c = payload[i];
        const bool alphabet = std::isalnum(static_cast<unsigned char>(c)) || c == '+' || c == '/';
        if (c == '=' && i + 2 >= payload.size()) { ++padding; continue; }
        if (!alphabet || padding > 0)
            return invalid(what + ": data URI payload is not valid base64 (character '" + std::string(1, c) +
                           "' at offset " + std::to_string(i) + ")");
    }
    return uint64_t(payload.size() / 4 * 3 - padding);
}

Result<std::filesystem::path> resolveFileUri(std::string_view uri, const LoadContext& context, const std::string& what) {
    if (uri.empty()) return invalid(what + ": uri is empty");
    if (hasScheme(uri))
        return invalid(what + ": uri " + shown(uri) + " has a scheme; only relative paths and data: URIs are allowed");
    const std::string decoded = urlDecode(uri);
    if (decoded.find('\0') != std::string::npos) return invalid(what + ": uri " + shown(uri) + " contains a NUL byte");
    if (decoded.find('\\') != std::string::npos)
        return invalid(what + ": uri " + shown(uri) + " contains a backslash (not a portable relative path)");
    if (decoded.front() == '/') return invalid(what + ": uri " + shown(uri) + " is an absolute path");
    for (const auto& segment : std::filesystem::path(decoded))
        if (segment == "..") return invalid(what + ": uri " + shown(uri) + " leaves the scene's folder (a '..' segment)");

    const std::filesystem::path path = context.folder / decoded;
    std::error_code ec;
    if (!std::filesystem::exists(path, ec))
        return ioFailed(what + ": file " + shown(decoded) + " not found in '" + context.folder.string() + "'");
    if (!insideFolder(context.folder, path))
        return invalid(what + ": uri " + shown(uri) + " resolves outside the scene's folder (through a symbolic link)");
    if (!std::filesystem::is_regular_file(path, ec)) return ioFailed(what + ": " + shown(decoded) + " is not a regular file");
    return path;
}

tinygltf::FsCallbacks fsCallbacks(LoadContext& context) {
    tinygltf::FsCallbacks callbacks{};
    callbacks.FileExists = &fileExists;
    callbacks.ExpandFilePath = &expandFilePath;
    callbacks.ReadWholeFile = &readWholeFile;
    callbacks.WriteWholeFile = &writeWholeFile;
    callbacks.user_data = &context;
    return callbacks;
}

} // namespace rrc::scene::detail
