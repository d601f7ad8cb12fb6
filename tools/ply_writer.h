// The bench meshes' output: binary little-endian PLY bytes, written to a file through a temporary and a rename.
#pragma once

#include <filesystem>
#include <string>

#include "tools/bench_mesh.h"

namespace raster::tools {

// Binary little-endian PLY: x y z nx ny nz as float, faces as a uchar count and uint indices.
std::string ply_bytes(const Mesh& mesh, const std::string& comment);

// Writes `bytes` to `path` through `path`.tmp and a rename; false (with a message) on failure.
bool write_atomically(const std::filesystem::path& path, const std::string& bytes);

}  // namespace raster::tools
