// One glTF primitive as raster's mesh data: its triangles from a list, strip or fan, with byte, short or int indices
// or none; its positions, normals, colours and texture coordinates; flat normals where the file gives none.
#pragma once

#include <optional>
#include <string>

#include "raster/gltf/gltf_accessors.h"
#include "raster/gltf/gltf_material.h"
#include "raster/gltf/gltf_warnings.h"
#include "raster/scene/mesh.h"

namespace raster {

// The primitive at JSON path `at` with its material; none for points and lines, which raster does not draw (the
// caller warns). Without NORMAL every triangle gets vertices of its own, so the normals raster derives from faces
// are the flat normals the spec asks for. Texture coordinates are kept when the material is textured, v flipped to
// raster's v-up convention.
std::optional<MeshData> read_gltf_primitive(const GltfAccessorReader& reader, const tinygltf::Primitive& primitive,
                                            const std::string& at, const GltfMaterial& material, GltfWarnings& warnings);

// The triangles of `vertex_count` indices of primitive mode 4 (list), 5 (strip) or 6 (fan), as the spec numbers
// them: strip triangle i is (i, i + 1 + i % 2, i + 2 - i % 2), fan triangle i is (i + 1, i + 2, 0). A list's
// indices past the last multiple of 3 make no triangle.
std::vector<TriangleIndices> gltf_triangles(int mode, const std::vector<uint32_t>& indices);

}  // namespace raster
