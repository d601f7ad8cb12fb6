// Orienting the teapot: patches agree across their seams, and each connected surface faces outwards.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "tools/teapot_mesh.h"

namespace raster::tools {

// Steps 3a and 3b: flips whole patches (triangle `i` belongs to patch `tri_patch[i]`) so that shared seam edges
// run in opposite directions and every surface's capped signed volume is positive; reports each surface on stderr.
void orient_patches(std::vector<Tri>& tris, const std::vector<std::uint32_t>& tri_patch, std::size_t npatch,
                    const std::vector<Vec3>& verts, double diag);

// Signed volume (divergence theorem, origin-independent) of a triangle set after closing every open
// boundary loop with a fan to that loop's centroid. Positive means the triangles face outwards.
double capped_signed_volume(const std::vector<Vec3>& v, const std::vector<Tri>& tris);

struct EdgeStats {
  std::size_t edges = 0, boundary = 0, manifold = 0, nonmanifold = 0, misoriented = 0;
};

// How the triangles' edges are shared: once (boundary), twice in opposite directions (manifold), twice the same
// way (misoriented), or more.
EdgeStats edge_stats(const std::vector<Tri>& tris);

}  // namespace raster::tools
