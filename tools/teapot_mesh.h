// What the teapot's stages share: triangles as vertex indices, degeneracy, undirected edge keys, union-find.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <utility>
#include <vector>

#include "tools/vec3.h"

namespace raster::tools {

using Tri = std::array<std::uint32_t, 3>;

inline double tri_area(const std::vector<Vec3>& v, const Tri& t) {
  return 0.5 * length(cross(v[t[1]] - v[t[0]], v[t[2]] - v[t[0]]));
}

inline bool degenerate(const std::vector<Vec3>& v, const Tri& t, double area_eps) {
  return t[0] == t[1] || t[1] == t[2] || t[0] == t[2] || tri_area(v, t) <= area_eps;
}

inline std::uint64_t edge_key(std::uint32_t a, std::uint32_t b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(a) << 32) | b;
}

struct UnionFind {
  std::vector<std::uint32_t> parent;
  explicit UnionFind(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0u); }
  std::uint32_t find(std::uint32_t a) {
    while (parent[a] != a) a = parent[a] = parent[parent[a]];
    return a;
  }
  void unite(std::uint32_t a, std::uint32_t b) { parent[find(a)] = find(b); }
};

}  // namespace raster::tools
