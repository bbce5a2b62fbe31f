// Internal: range-checked access to glTF accessor data. viewAccessor() checks everything an
// element read depends on (type, component type, bufferView and buffer bounds, stride,
// alignment) with overflow-checked 64-bit arithmetic, so AccessorView reads never leave the buffer.
#pragma once
#include "load_context.hpp"

#include <tiny_gltf.h>

#include <initializer_list>

namespace rrc::scene::detail {

struct Format {
    int componentType;    // TINYGLTF_COMPONENT_TYPE_*
    bool normalized;
};

class AccessorView {
public:
    size_t count = 0;
    int components = 0;

    // Component c of element i as a number; normalized integers map to [0,1] / [-1,1].
    double get(size_t i, int c) const;
    // Component c of element i as an unsigned integer (integer component types only).
    uint32_t getUint(size_t i, int c) const;

private:
    friend Result<AccessorView> viewAccessor(const tinygltf::Model&, int, const std::string&, int,
                                             std::initializer_list<Format>, bool);
    const unsigned char* data_ = nullptr;  // null: the accessor has no bufferView (all zeros)
    size_t stride_ = 0;
    int componentType_ = 0;
    bool normalized_ = false;
};

// "accessor 3 (indices of mesh 0 primitive 0)" or "accessor 3" without a use.
std::string describeAccessor(int index, const std::string& use);

// Checks accessor `index` for the given use. `type` is TINYGLTF_TYPE_* (or 0 for any) and
// `formats` the allowed component type / normalized pairs (empty for any glTF combination).
// Sparse accessors are refused unless `sparseAllowed` (then only the dense base is checked and
// the view must not be read): the loader reads none, but files may carry them for morph targets.
Result<AccessorView> viewAccessor(const tinygltf::Model& model, int index, const std::string& use, int type,
                                  std::initializer_list<Format> formats, bool sparseAllowed = false);

} // namespace rrc::scene::detail
