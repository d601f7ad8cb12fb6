// Internal to raster_formats (the PLY reader): a PLY body's elements read into MeshData, after its header.
#pragma once

#include <string>
#include <string_view>

#include "raster/formats/ply_header.h"
#include "raster/scene/mesh.h"

namespace raster::ply {

// Reads `body`, the bytes after the header (`bytes_before` of them precede it in the file), into `mesh`: vertex
// positions, colours and normals, faces fan-triangulated with their colours; other elements and properties are
// read past. Throws InputError (`name` names the file) on any bad value, a truncated body or data after it.
void read_body(const Header& header, std::string_view body, size_t bytes_before, const std::string& name,
               MeshData& mesh);

}  // namespace raster::ply
