// Welding the teapot's vertices: within 1e-6 while tessellating, then exactly as written, and bowtie vertices split.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include "tools/teapot_mesh.h"
#include "tools/teapot_obj_writer.h"

namespace raster::tools {

inline constexpr double kWeldTolerance = 1e-6;

// Welds points that lie within kWeldTolerance of an earlier point (quantised grid, 27-cell search).
class Welder {
 public:
  std::uint32_t add(Vec3 p) {
    const std::array<long long, 3> q = quantise(p);
    for (long long dx = -1; dx <= 1; ++dx)
      for (long long dy = -1; dy <= 1; ++dy)
        for (long long dz = -1; dz <= 1; ++dz) {
          auto it = cells_.find(Key{q[0] + dx, q[1] + dy, q[2] + dz});
          if (it == cells_.end()) continue;
          for (std::uint32_t id : it->second)
            if (length(points_[id] - p) <= kWeldTolerance) return id;
        }
    const auto id = static_cast<std::uint32_t>(points_.size());
    points_.push_back(p);
    cells_[Key{q[0], q[1], q[2]}].push_back(id);
    return id;
  }
  const std::vector<Vec3>& points() const { return points_; }

 private:
  struct Key {
    long long x, y, z;
    bool operator==(const Key&) const = default;
  };
  struct KeyHash {
    std::size_t operator()(const Key& k) const {
      std::uint64_t h = 1469598103934665603ull;
      for (long long v : {k.x, k.y, k.z}) h = (h ^ static_cast<std::uint64_t>(v)) * 1099511628211ull;
      return static_cast<std::size_t>(h ^ (h >> 29));
    }
  };
  static std::array<long long, 3> quantise(Vec3 p) {
    return {std::llround(p.x / kWeldTolerance), std::llround(p.y / kWeldTolerance), std::llround(p.z / kWeldTolerance)};
  }
  std::vector<Vec3> points_;
  std::unordered_map<Key, std::vector<std::uint32_t>, KeyHash> cells_;
};

// Step 5: every vertex rounded to the text the OBJ will hold, vertices with the same text welded, triangles that
// became degenerate dropped (added to `dropped`), and the vertices only they used left out.
WrittenMesh round_and_reweld(const std::vector<Vec3>& verts, const std::vector<Tri>& tris, double area_eps,
                             std::size_t& dropped);

// Step 5b: one copy of a vertex per fan of triangles around it; returns how many vertices were split.
std::size_t split_bowtie_vertices(WrittenMesh& mesh);

}  // namespace raster::tools
