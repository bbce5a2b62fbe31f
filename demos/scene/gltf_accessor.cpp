// Accessor checks and element reads (glTF 2.0 spec 3.6.2: data alignment, byteStride, and the
// accessor-fits-in-bufferView rule offset + stride * (count - 1) + elementSize <= byteLength).
#include "gltf_accessor.hpp"

#include <algorithm>
#include <cstring>

namespace rrc::scene::detail {
namespace {

std::string typeName(int type) {
    switch (type) {
    case TINYGLTF_TYPE_SCALAR: return "SCALAR";
    case TINYGLTF_TYPE_VEC2: return "VEC2";
    case TINYGLTF_TYPE_VEC3: return "VEC3";
    case TINYGLTF_TYPE_VEC4: return "VEC4";
    case TINYGLTF_TYPE_MAT2: return "MAT2";
    case TINYGLTF_TYPE_MAT3: return "MAT3";
    case TINYGLTF_TYPE_MAT4: return "MAT4";
    default: return "type " + std::to_string(type);
    }
}

std::string formatName(Format f) {
    std::string name;
    switch (f.componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: name = "byte"; break;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: name = "unsigned byte"; break;
    case TINYGLTF_COMPONENT_TYPE_SHORT: name = "short"; break;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: name = "unsigned short"; break;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: name = "unsigned int"; break;
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return "float";
    default: return "componentType " + std::to_string(f.componentType);
    }
    return (f.normalized ? "normalized " : "") + name;
}

// Bytes per component; 0 for component types glTF 2.0 does not allow (tinygltf accepts double).
size_t componentSize(int componentType) {
    switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
    default: return 0;
    }
}

// Element size including the 4-byte column alignment of small-component matrices.
size_t elementSize(int type, size_t componentSize) {
    const int components = tinygltf::GetNumComponentsInType(uint32_t(type));
    if (type == TINYGLTF_TYPE_MAT2 && componentSize == 1) return 8;
    if (type == TINYGLTF_TYPE_MAT3 && componentSize == 1) return 12;
    if (type == TINYGLTF_TYPE_MAT3 && componentSize == 2) return 24;
    return size_t(components) * componentSize;
}

template <class T>
T load(const unsigned char* p) {
    T value;
    std::memcpy(&value, p, sizeof value);  // the data need not be aligned for T
    return value;
}

} // namespace

std::string describeAccessor(int index, const std::string& use) {
    return "accessor " + std::to_string(index) + (use.empty() ? "" : " (" + use + ")");
}

double AccessorView::get(size_t i, int c) const {
    if (!data_) return 0.0;
    const unsigned char* p = data_ + i * stride_ + size_t(c) * componentSize(componentType_);
    switch (componentType_) {
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return load<float>(p);
    case TINYGLTF_COMPONENT_TYPE_BYTE: { const double v = load<int8_t>(p); return normalized_ ? std::max(v / 127.0, -1.0) : v; }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: { const double v = load<uint8_t>(p); return normalized_ ? v / 255.0 : v; }
    case TINYGLTF_COMPONENT_TYPE_SHORT: { const double v = load<int16_t>(p); return normalized_ ? std::max(v / 32767.0, -1.0) : v; }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: { const double v = load<uint16_t>(p); return normalized_ ? v / 65535.0 : v; }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return load<uint32_t>(p);
    default: return 0.0;
    }
}

uint32_t AccessorView::getUint(size_t i, int c) const {
    if (!data_) return 0;
    const unsigned char* p = data_ + i * stride_ + size_t(c) * componentSize(componentType_);
    switch (componentType_) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return load<uint8_t>(p);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return load<uint16_t>(p);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return load<uint32_t>(p);
    default: return 0;
    }
}

Result<AccessorView> viewAccessor(const tinygltf::Model& model, int index, const std::string& use, int type,
                                  std::initializer_list<Format> formats, bool sparseAllowed) {
    const std::string what = describeAccessor(index, use);
    if (index < 0 || size_t(index) >= model.accessors.size())
        return invalid(what + " does not exist (" + std::to_string(model.accessors.size()) + " accessors)");
    const tinygltf::Accessor& a = model.accessors[size_t(index)];
    if (a.sparse.isSparse && !sparseAllowed) return invalid(what + ": sparse accessors are not supported");
    const int components = tinygltf::GetNumComponentsInType(uint32_t(a.type));
    if (components <= 0) return invalid(what + ": unknown type " + std::to_string(a.type));
    if (type != 0 && a.type != type) return invalid(what + ": type " + typeName(a.type) + ", expected " + typeName(type));
    const size_t componentBytes = componentSize(a.componentType);
    if (componentBytes == 0) return invalid(what + ": componentType " + std::to_string(a.componentType) + " is not allowed in glTF 2.0");
    const bool integer = a.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT;
    if (a.normalized && (!integer || a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT))
        return invalid(what + ": only byte and short components can be normalized");
    const Format format{a.componentType, integer && a.normalized};
    if (formats.size() && std::none_of(formats.begin(), formats.end(), [&](Format f) {
            return f.componentType == format.componentType && f.normalized == format.normalized; })) {
        std::string allowed;
        for (Format f : formats) allowed += (allowed.empty() ? "" : " or ") + formatName(f);
        return invalid(what + ": " + formatName(format) + " components are not allowed here (expected " + allowed + ")");
    }
    if (a.count == 0) return invalid(what + ": count must be at least 1");

    AccessorView view;
    view.count = a.count;
    view.components = components;
    view.componentType_ = a.componentType;
    view.normalized_ = format.normalized;
    if (a.bufferView < 0) return view;  // glTF: an accessor without a bufferView holds zeros

    if (size_t(a.bufferView) >= model.bufferViews.size())
        return invalid(what + ": bufferView " + std::to_string(a.bufferView) + " does not exist (" +
                       std::to_string(model.bufferViews.size()) + " bufferViews)");
    const tinygltf::BufferView& bv = model.bufferViews[size_t(a.bufferView)];
    const std::string viewName = "bufferView " + std::to_string(a.bufferView);
    if (bv.buffer < 0 || size_t(bv.buffer) >= model.buffers.size())
        return invalid(what + ": " + viewName + " refers to missing buffer " + std::to_string(bv.buffer));
    const size_t bufferSize = model.buffers[size_t(bv.buffer)].data.size();
    uint64_t viewEnd = 0;
    if (!mulAdd(1, bv.byteOffset, bv.byteLength, viewEnd) || viewEnd > bufferSize)
        return invalid(what + ": " + viewName + " runs past the end of buffer " + std::to_string(bv.buffer));

    const size_t elementBytes = elementSize(a.type, componentBytes);
    const size_t stride = bv.byteStride ? bv.byteStride : elementBytes;
    if (stride < elementBytes)
        return invalid(what + ": " + viewName + " byteStride " + std::to_string(stride) + " is smaller than the " +
                       std::to_string(elementBytes) + "-byte element");
    if (a.byteOffset % componentBytes || (bv.byteOffset + a.byteOffset) % componentBytes || stride % componentBytes)
        return invalid(what + ": byteOffset " + std::to_string(a.byteOffset) + " (" + std::to_string(bv.byteOffset + a.byteOffset) +
                       " in the buffer, stride " + std::to_string(stride) + ") is not aligned to its " +
                       std::to_string(componentBytes) + "-byte components");
    uint64_t end = 0;
    if (!mulAdd(stride, a.count - 1, elementBytes, end) || !mulAdd(1, end, a.byteOffset, end) || end > bv.byteLength)
        return invalid(what + ": " + std::to_string(a.count) + " elements of " + std::to_string(elementBytes) + " bytes (stride " +
                       std::to_string(stride) + ", byteOffset " + std::to_string(a.byteOffset) + ") run past the end of " +
                       viewName + " (" + std::to_string(bv.byteLength) + " bytes)");
    view.data_ = model.buffers[size_t(bv.buffer)].data.data() + bv.byteOffset + a.byteOffset;
    view.stride_ = stride;
    return view;
}

} // namespace rrc::scene::detail
