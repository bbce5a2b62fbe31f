// Decodes glTF images with Debian's stb_image (libstb) into RGBA8, refusing other formats and
// images too large for the options before any pixel memory is allocated.
#include "gltf_image.hpp"

#include "load_context.hpp"

#include <stb_image.h>

#include <cstring>
#include <memory>

namespace rrc::scene::detail {
namespace {

bool isPng(const unsigned char* b, int n) { return n >= 8 && std::memcmp(b, "\x89PNG\r\n\x1a\n", 8) == 0; }
bool isJpeg(const unsigned char* b, int n) { return n >= 3 && b[0] == 0xFF && b[1] == 0xD8 && b[2] == 0xFF; }

bool failed(std::string* err, int index, const std::string& what) {
    if (err) *err += "image " + std::to_string(index) + ": " + what;
    return false;
}

struct StbFree {
    void operator()(stbi_uc* p) const { stbi_image_free(p); }
};

} // namespace

bool loadImageData(tinygltf::Image* image, int imageIndex, std::string* err, std::string*, int, int,
                   const unsigned char* bytes, int size, void* userPointer) {
    auto& context = *static_cast<LoadContext*>(userPointer);
    if (!bytes || size <= 0) return failed(err, imageIndex, "no image data");
    if (image->bufferView >= 0) {
        // tinygltf has already formed `bytes` from this bufferView without checking it; make sure
        // the range it stands for lies inside its buffer before anything reads from it. (The JSON
        // pre-check refuses such files earlier; this guards the reads should that ever change.)
        const auto view = size_t(image->bufferView);
        if (view >= context.views.size()) return failed(err, imageIndex, "bufferView " + std::to_string(view) + " does not exist");
        const LoadContext::ViewRange& r = context.views[view];
        uint64_t end = 0;
        if (r.buffer >= context.bufferLengths.size() || !mulAdd(1, r.offset, r.length, end) ||
            end > context.bufferLengths[r.buffer] || uint64_t(size) != r.length)
            return failed(err, imageIndex, "bufferView " + std::to_string(view) + " lies outside its buffer");
    }
    // stb_image understands many formats; glTF allows two, and fewer decoders means less exposure.
    if (!isPng(bytes, size) && !isJpeg(bytes, size))
        return failed(err, imageIndex, "not a PNG or JPEG file (mimeType '" + image->mimeType + "')");
    int width = 0, height = 0, channels = 0;
    if (!stbi_info_from_memory(bytes, size, &width, &height, &channels))
        return failed(err, imageIndex, std::string("cannot decode: ") + stbi_failure_reason());
    const int maxSize = context.options.maxImageSize;
    if (width <= 0 || height <= 0 || width > maxSize || height > maxSize)
        return failed(err, imageIndex, "size " + std::to_string(width) + "x" + std::to_string(height) +
                                           " is outside 1.." + std::to_string(maxSize));
    const uint64_t pixelBytes = uint64_t(width) * uint64_t(height) * 4;
    if (!context.charge(pixelBytes, "image " + std::to_string(imageIndex) + " (decoded)"))
        return failed(err, imageIndex, context.budgetError);

    int w = 0, h = 0, c = 0;
    std::unique_ptr<stbi_uc, StbFree> pixels(stbi_load_from_memory(bytes, size, &w, &h, &c, 4));
    if (!pixels) return failed(err, imageIndex, std::string("cannot decode: ") + stbi_failure_reason());
    if (w != width || h != height) return failed(err, imageIndex, "decoded size differs from its header");
    image->width = w;
    image->height = h;
    image->component = 4;
    image->bits = 8;
    image->pixel_type = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
    image->image.assign(pixels.get(), pixels.get() + pixelBytes);
    image->as_is = false;
    return true;
}

} // namespace rrc::scene::detail
