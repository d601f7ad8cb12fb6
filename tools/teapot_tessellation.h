// The teapot's bicubic patches evaluated on a grid, welded, and split into triangles in their (u,v) order.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "tools/teapot_mesh.h"
#include "tools/teapot_patch_data.h"

namespace raster::tools {

// Every patch's (steps+1)^2 grid of points, welded across seams, as triangles; degenerate ones are dropped
// (and counted). `diag` is the diagonal of the points' bounding box, `area_eps` the degenerate-area threshold.
struct PatchTriangles {
  std::vector<Vec3> verts;
  std::vector<Tri> tris;
  std::vector<std::uint32_t> tri_patch;  // the patch each triangle comes from
  std::size_t dropped = 0;
  double diag = 0, area_eps = 0;
};

PatchTriangles tessellate_patches(const PatchData& data, int steps);

}  // namespace raster::tools
