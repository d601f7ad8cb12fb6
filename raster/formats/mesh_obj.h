// Wavefront OBJ meshes, read by raster's own reader: objects, normals and vertex colours, polygons triangulated.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "raster/scene/mesh.h"

namespace raster {

// Parses OBJ text; `name` is used in error messages only. The objects of the file (`o`/`g`; which of them are kept
// is tinyobjloader's rule, see mesh_obj_reader.cpp) are kept in order in one MeshData, object_names /
// object_first_triangle marking where each starts. Normals are kept when
// every face corner has one; vertex colours (`v x y z r g b`) when every vertex has one; texture coordinates, per
// triangle corner, when every corner has one. `usemtl` runs and `mtllib` names are kept for the scene to resolve
// (obj_materials.h); the material files are not read here. Throws InputError on malformed input, indices out of
// range, non-finite coordinates or sizes over the limits in mesh.h.
MeshData parse_obj(std::string_view text, const std::string& name);

// Reads and parses an OBJ file (at most 2 GiB). Throws InputError naming the file.
MeshData load_obj(const std::filesystem::path& path);

}  // namespace raster
