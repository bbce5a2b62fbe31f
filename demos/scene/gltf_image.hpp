// Internal: the image decoder tinygltf calls (SetImageLoader). PNG and JPEG only, dimensions and
// the byte budget checked from the header before stb_image allocates, always decoded to RGBA8.
// tinygltf hands over a pointer into an image's bufferView without checking the view (upstream
// PR #512): the JSON pre-check refuses such files, and this callback checks the view's declared
// range against its buffer again before stb_image reads a byte.
#pragma once
#include <tiny_gltf.h>

namespace rrc::scene::detail {

// tinygltf::LoadImageDataFunction; user_pointer is the LoadContext.
bool loadImageData(tinygltf::Image* image, int imageIndex, std::string* err, std::string* warn, int requestedWidth,
                   int requestedHeight, const unsigned char* bytes, int size, void* userPointer);

} // namespace rrc::scene::detail
