// Mesh files by extension: Wavefront OBJ or Stanford PLY.
#pragma once

#include <filesystem>
#include <string_view>

#include "raster/scene/mesh.h"

namespace raster {

// Whether `path` names a mesh file: its extension is .obj or .ply, in any case.
bool is_mesh_file(const std::filesystem::path& path);

// Loads a mesh file by extension: .obj (Wavefront) or .ply (Stanford). Throws InputError.
MeshData load_mesh_file(const std::filesystem::path& path);
// The same from the file's bytes already in memory; `path` names the format and the file in messages.
MeshData parse_mesh_file(std::string_view bytes, const std::filesystem::path& path);

}  // namespace raster
