// Mesh files by extension: Wavefront OBJ or Stanford PLY.
#pragma once

#include <filesystem>

#include "raster/scene/mesh.h"

namespace raster {

// Loads a mesh file by extension: .obj (Wavefront) or .ply (Stanford). Throws InputError.
MeshData load_mesh_file(const std::filesystem::path& path);

}  // namespace raster
