// glTF accessors read with every index, offset, stride and length checked against the buffers first, so a hostile
// file fails with the JSON path of its problem (`/accessors/3/count`) instead of reading past a buffer.
#pragma once

#include <cstdint>
#include <initializer_list>
#include <string>
#include <vector>

#include "raster/gltf/tiny_gltf_config.h"

namespace raster {

class GltfAccessorReader {
public:
    // `file` names the model in messages; the model must outlive the reader.
    GltfAccessorReader(const tinygltf::Model& model, std::string file);

    // The elements of accessor `index`, `use` (the JSON path that names it) in messages, as floats: `types` are the
    // element types allowed (TINYGLTF_TYPE_VEC3, ...); floats are read as they are and, where `normalized_types`
    // allows the component type and the accessor says normalized, integers as the spec maps them to [0, 1] or
    // [-1, 1]. Each element's components follow each other; returns count x components values, all finite.
    std::vector<float> floats(int index, const std::string& use, std::initializer_list<int> types,
                              std::initializer_list<int> normalized_types, int& components) const;

    // The elements of an index accessor (unsigned byte, short or int scalars), each below `vertex_count`.
    std::vector<uint32_t> indices(int index, const std::string& use, size_t vertex_count) const;

    // How many elements accessor `index` has, checked as floats() and indices() check it.
    size_t count(int index, const std::string& use) const;

    [[noreturn]] void fail(const std::string& json_path, const std::string& message) const;

private:
    struct Layout;
    Layout layout(int index, const std::string& use, std::initializer_list<int> types,
                  const std::vector<int>& component_types) const;

    const tinygltf::Model& model_;
    std::string file_;
};

// The most elements an accessor may have: enough for the largest mesh raster loads (mesh.h) as a triangle list.
inline constexpr uint64_t kMaxGltfAccessorCount = uint64_t{3} << 24;

}  // namespace raster
