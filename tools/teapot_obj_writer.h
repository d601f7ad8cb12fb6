// The teapot as an OBJ file: vertices as 6-significant-digit text, a header naming the source, an atomic write.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "tools/teapot_mesh.h"

namespace raster::tools {

// A coordinate as the OBJ holds it: %.6g, with values within 1e-12 of zero written as 0.
std::string fmt6(double x);

// The mesh as it will be written: each vertex, its "x y z" text, and the triangles.
struct WrittenMesh {
  std::vector<Vec3> verts;
  std::vector<std::string> text;
  std::vector<Tri> tris;
};

// Step 7: writes OUT.tmp, then renames it over `out_path`; false, with a message on stderr, when that fails.
bool write_obj(const std::string& out_path, const std::string& data_path, std::size_t npatch, std::size_t npoints,
               int steps, const WrittenMesh& mesh);

}  // namespace raster::tools
