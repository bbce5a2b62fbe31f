// Internal to loadScene(): what every loading step shares (options, the scene's folder, the byte
// budget) and helpers that build unlogged errors; loadScene() prefixes the path and logs once.
#pragma once
#include "scene.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace rrc::scene::detail {

struct LoadContext {
    // The byte range of a bufferView as declared in the JSON (checked against its buffer).
    struct ViewRange {
        uint64_t buffer = 0, offset = 0, length = 0;
    };

    LoadOptions options;
    std::filesystem::path folder;    // canonical folder of the scene file; nothing outside is read
    uint64_t bytesUsed = 0;
    std::string budgetError;         // set when charge() refused
    std::vector<uint64_t> bufferLengths;  // declared byteLength per buffer (the pre-check's view)
    std::vector<ViewRange> views;         // per bufferView, filled by the pre-check

    // Counts `bytes` against options.maxBytes; false (and budgetError set) when over the cap.
    bool charge(uint64_t bytes, const std::string& what) {
        if (bytes > options.maxBytes || bytesUsed > options.maxBytes - bytes) {
            budgetError = what + " needs " + std::to_string(bytes) + " bytes, over the load limit of " +
                          std::to_string(options.maxBytes) + " bytes (" + std::to_string(bytesUsed) +
                          " already used)";
            return false;
        }
        bytesUsed += bytes;
        return true;
    }
};

inline Error invalid(std::string what) { return Error{LogId::SceneInvalid, std::move(what)}; }
inline Error ioFailed(std::string what) { return Error{LogId::SceneLoadFailed, std::move(what)}; }

// a * b + c without wrapping; false on overflow.
inline bool mulAdd(uint64_t a, uint64_t b, uint64_t c, uint64_t& out) {
    uint64_t product = 0;
    return !__builtin_mul_overflow(a, b, &product) && !__builtin_add_overflow(product, c, &out);
}

} // namespace rrc::scene::detail
