// glTF accessors, read with every range checked (gltf_accessors.h).
#include "raster/gltf/gltf_accessors.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "raster/core/errors.h"

namespace raster {

namespace {

int component_bytes(int component_type) {
    switch (component_type) {
        case TINYGLTF_COMPONENT_TYPE_BYTE:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
        case TINYGLTF_COMPONENT_TYPE_SHORT:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
        default: return 0;
    }
}

const char* component_name(int component_type) {
    switch (component_type) {
        case TINYGLTF_COMPONENT_TYPE_BYTE: return "byte";
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return "unsigned byte";
        case TINYGLTF_COMPONENT_TYPE_SHORT: return "short";
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return "unsigned short";
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return "unsigned int";
        case TINYGLTF_COMPONENT_TYPE_FLOAT: return "float";
        default: return "unknown";
    }
}

int type_components(int type) {
    switch (type) {
        case TINYGLTF_TYPE_SCALAR: return 1;
        case TINYGLTF_TYPE_VEC2: return 2;
        case TINYGLTF_TYPE_VEC3: return 3;
        case TINYGLTF_TYPE_VEC4: return 4;
        default: return 0;
    }
}

bool contains(std::initializer_list<int> list, int value) {
    return std::find(list.begin(), list.end(), value) != list.end();
}

// One component at `p`, as the spec maps it: floats as they are, normalized integers to [0, 1] or [-1, 1].
float component_value(const unsigned char* p, int component_type) {
    switch (component_type) {
        case TINYGLTF_COMPONENT_TYPE_FLOAT: {
            float f;
            std::memcpy(&f, p, 4);
            return f;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return static_cast<float>(p[0]) / 255.0f;
        case TINYGLTF_COMPONENT_TYPE_BYTE:
            return std::max(static_cast<float>(static_cast<int8_t>(p[0])) / 127.0f, -1.0f);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
            uint16_t u;
            std::memcpy(&u, p, 2);
            return static_cast<float>(u) / 65535.0f;
        }
        default: {  // short
            int16_t s;
            std::memcpy(&s, p, 2);
            return std::max(static_cast<float>(s) / 32767.0f, -1.0f);
        }
    }
}

uint32_t index_value(const unsigned char* p, int component_type) {
    if (component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE) return p[0];
    if (component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) {
        uint16_t u;
        std::memcpy(&u, p, 2);
        return u;
    }
    uint32_t u;
    std::memcpy(&u, p, 4);
    return u;
}

}  // namespace

// Where an accessor's elements are: `data` null when it has no buffer view (every element zero).
struct GltfAccessorReader::Layout {
    const tinygltf::Accessor* accessor = nullptr;
    const unsigned char* data = nullptr;
    size_t stride = 0;
    int components = 0;
};

GltfAccessorReader::GltfAccessorReader(const tinygltf::Model& model, std::string file)
    : model_(model), file_(std::move(file)) {}

void GltfAccessorReader::fail(const std::string& json_path, const std::string& message) const {
    throw InputError(file_, 0, 0, json_path + ": " + message);
}

GltfAccessorReader::Layout GltfAccessorReader::layout(int index, const std::string& use, std::initializer_list<int> types,
                                                      const std::vector<int>& component_types) const {
    if (index < 0 || static_cast<size_t>(index) >= model_.accessors.size())
        fail(use, "there is no accessor " + std::to_string(index));
    const tinygltf::Accessor& accessor = model_.accessors[static_cast<size_t>(index)];
    const std::string at = "/accessors/" + std::to_string(index);
    if (accessor.sparse.isSparse) fail(at + "/sparse", "sparse accessors are not supported");
    if (!contains(types, accessor.type)) fail(at + "/type", "this type of element cannot be " + use);
    if (std::find(component_types.begin(), component_types.end(), accessor.componentType) == component_types.end())
        fail(at + "/componentType", std::string(component_name(accessor.componentType)) + " components cannot be " + use);
    if (accessor.count < 1 || accessor.count > kMaxGltfAccessorCount)
        fail(at + "/count", std::to_string(accessor.count) + " elements; raster reads 1 to " +
                                std::to_string(kMaxGltfAccessorCount));
    Layout out;
    out.accessor = &accessor;
    out.components = type_components(accessor.type);
    const size_t element = static_cast<size_t>(out.components) * component_bytes(accessor.componentType);
    if (accessor.bufferView < 0) return out;  // zeros, as the spec says of an accessor without a view
    if (static_cast<size_t>(accessor.bufferView) >= model_.bufferViews.size())
        fail(at + "/bufferView", "there is no buffer view " + std::to_string(accessor.bufferView));
    const std::string view_at = "/bufferViews/" + std::to_string(accessor.bufferView);
    const tinygltf::BufferView& view = model_.bufferViews[static_cast<size_t>(accessor.bufferView)];
    if (view.buffer < 0 || static_cast<size_t>(view.buffer) >= model_.buffers.size())
        fail(view_at + "/buffer", "there is no buffer " + std::to_string(view.buffer));
    const std::vector<unsigned char>& buffer = model_.buffers[static_cast<size_t>(view.buffer)].data;
    if (view.byteOffset > buffer.size() || view.byteLength > buffer.size() - view.byteOffset)
        fail(view_at + "/byteLength", "bytes " + std::to_string(view.byteOffset) + " + " + std::to_string(view.byteLength) +
                                          " run past the buffer's " + std::to_string(buffer.size()));
    out.stride = view.byteStride ? view.byteStride : element;
    if (out.stride < element || out.stride > 252)
        fail(view_at + "/byteStride", std::to_string(view.byteStride) + " bytes between elements of " +
                                          std::to_string(element) + " bytes; the spec allows " + std::to_string(element) +
                                          " to 252");
    // count <= 3 * 2^24 and stride <= 252: no product below overflows.
    const uint64_t span = uint64_t{out.stride} * (accessor.count - 1) + element;
    if (accessor.byteOffset > view.byteLength || span > view.byteLength - accessor.byteOffset)
        fail(at + "/count", std::to_string(accessor.count) + " elements from byte " + std::to_string(accessor.byteOffset) +
                                " run past the buffer view's " + std::to_string(view.byteLength) + " bytes");
    out.data = buffer.data() + view.byteOffset + accessor.byteOffset;
    return out;
}

size_t GltfAccessorReader::count(int index, const std::string& use) const {
    return layout(index, use,
                  {TINYGLTF_TYPE_SCALAR, TINYGLTF_TYPE_VEC2, TINYGLTF_TYPE_VEC3, TINYGLTF_TYPE_VEC4},
                  {TINYGLTF_COMPONENT_TYPE_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_SHORT,
                   TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT,
                   TINYGLTF_COMPONENT_TYPE_FLOAT})
        .accessor->count;
}

std::vector<float> GltfAccessorReader::floats(int index, const std::string& use, std::initializer_list<int> types,
                                              std::initializer_list<int> normalized_types, int& components) const {
    std::vector<int> allowed{TINYGLTF_COMPONENT_TYPE_FLOAT};
    const tinygltf::Accessor* accessor =
        index >= 0 && static_cast<size_t>(index) < model_.accessors.size() ? &model_.accessors[static_cast<size_t>(index)] : nullptr;
    if (accessor && accessor->normalized && contains(normalized_types, accessor->componentType))
        allowed.push_back(accessor->componentType);
    const Layout l = layout(index, use, types, allowed);
    components = l.components;
    std::vector<float> out(l.accessor->count * static_cast<size_t>(l.components), 0.0f);
    if (!l.data) return out;
    const int bytes = component_bytes(l.accessor->componentType);
    for (size_t i = 0; i < l.accessor->count; ++i) {
        const unsigned char* element = l.data + i * l.stride;
        for (int c = 0; c < l.components; ++c) {
            const float value = component_value(element + c * bytes, l.accessor->componentType);
            if (!std::isfinite(value))
                fail("/accessors/" + std::to_string(index), "element " + std::to_string(i) + " is not a finite number");
            out[i * static_cast<size_t>(l.components) + c] = value;
        }
    }
    return out;
}

std::vector<uint32_t> GltfAccessorReader::indices(int index, const std::string& use, size_t vertex_count) const {
    const Layout l = layout(index, use, {TINYGLTF_TYPE_SCALAR},
                            {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                             TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT});
    std::vector<uint32_t> out(l.accessor->count, 0u);
    if (!l.data) return out;
    for (size_t i = 0; i < l.accessor->count; ++i) {
        out[i] = index_value(l.data + i * l.stride, l.accessor->componentType);
        if (out[i] >= vertex_count)
            fail("/accessors/" + std::to_string(index), "index " + std::to_string(out[i]) + " (element " +
                                                            std::to_string(i) + ") is past the primitive's " +
                                                            std::to_string(vertex_count) + " vertices");
    }
    return out;
}

}  // namespace raster
