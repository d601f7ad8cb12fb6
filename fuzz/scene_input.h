// The shared body of the scene-format fuzz targets: a scene file's text through raster::parse_scene, in a sandbox.
#pragma once

#include <cstddef>
#include <cstdint>

namespace raster::fuzz {

// Parses the bytes as a scene file named `file_name` inside a sandbox folder that holds small valid meshes
// (tri.obj, quad.ply, tri_binary.ply), so scenes that name them load and validate fully, and any other mesh name
// fails cleanly. Inputs that could spell a '/' are skipped (see could_spell_a_slash). Always returns 0.
int fuzz_scene_text(const uint8_t* data, size_t size, const char* file_name);

}  // namespace raster::fuzz
