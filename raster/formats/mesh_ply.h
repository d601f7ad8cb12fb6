// Stanford PLY mesh loader (ascii 1.0 and binary_little_endian 1.0), hand-written and hardened against hostile input.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "raster/scene/mesh.h"

namespace raster {

// Parses PLY bytes; `name` is used in error messages only (and its stem names the single object of the mesh).
// Throws InputError on any bad input: header errors and ascii body errors carry the 1-based line (and column when
// a token is at fault); binary body errors carry line 0 and give the byte offset in the message.
//
// Reads element `vertex` (x y z required; optional red green blue, optional nx ny nz) and element `face`
// (list `vertex_indices` or `vertex_index`, polygons fan-triangulated; optional per-face red green blue stored in
// face_colors, one per output triangle). Every other property and element is skipped. Optional attributes are
// stored only when present in the file. Trailing data after the last declared element is an error.
MeshData parse_ply(std::string_view bytes, const std::string& name);

// Reads and parses a PLY file (at most 2 GiB). Throws InputError naming the file on any I/O or format error.
MeshData load_ply(const std::filesystem::path& path);

}  // namespace raster
