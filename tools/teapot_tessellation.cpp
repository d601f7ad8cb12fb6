// Bezier evaluation of the teapot's patches (Bernstein basis) and their triangles, in the data's own Z-up frame.
#include "tools/teapot_tessellation.h"

#include <algorithm>
#include <array>
#include <utility>

#include "tools/teapot_welding.h"

namespace raster::tools {

namespace {

std::array<double, 4> bernstein(double t) {
  const double s = 1.0 - t;
  return {s * s * s, 3.0 * t * s * s, 3.0 * t * t * s, t * t * t};
}

}  // namespace

PatchTriangles tessellate_patches(const PatchData& data, int steps) {
  // 1. Evaluate and weld (in the data's own Z-up frame; the later transform is exact).
  const int n = steps;
  const std::size_t npatch = data.patches.size();
  Welder welder;
  std::vector<std::vector<std::uint32_t>> grid(npatch);  // (n+1)^2 welded ids, index a*(n+1)+b
  std::vector<std::array<double, 4>> basis(static_cast<std::size_t>(n) + 1);
  for (int i = 0; i <= n; ++i) basis[static_cast<std::size_t>(i)] = bernstein(i == n ? 1.0 : static_cast<double>(i) / n);
  for (std::size_t p = 0; p < npatch; ++p) {
    const auto& idx = data.patches[p];
    grid[p].reserve(static_cast<std::size_t>((n + 1) * (n + 1)));
    for (int a = 0; a <= n; ++a)
      for (int b = 0; b <= n; ++b) {
        const auto& bu = basis[static_cast<std::size_t>(a)];  // along the rows (u)
        const auto& bv = basis[static_cast<std::size_t>(b)];  // along the columns (v)
        Vec3 s{};
        for (int r = 0; r < 4; ++r)
          for (int c = 0; c < 4; ++c)
            s = s + (bu[static_cast<std::size_t>(r)] * bv[static_cast<std::size_t>(c)]) * data.points[idx[static_cast<std::size_t>(4 * r + c)]];
        grid[p].push_back(welder.add(s));
      }
  }
  std::vector<Vec3> verts = welder.points();

  Vec3 lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
  for (const Vec3& v : verts) {
    lo = {std::min(lo.x, v.x), std::min(lo.y, v.y), std::min(lo.z, v.z)};
    hi = {std::max(hi.x, v.x), std::max(hi.y, v.y), std::max(hi.z, v.z)};
  }
  const double diag = std::max(length(hi - lo), 1e-30);
  const double area_eps = 1e-14 * diag * diag;

  // 2. Triangles in each patch's natural (u,v) order: normal along dS/du x dS/dv. Drop degenerates.
  std::vector<Tri> tris;
  std::vector<std::uint32_t> tri_patch;
  std::size_t dropped = 0;
  const auto w = static_cast<std::size_t>(n) + 1;
  for (std::size_t p = 0; p < npatch; ++p)
    for (std::size_t a = 0; a < w - 1; ++a)
      for (std::size_t b = 0; b < w - 1; ++b) {
        const std::uint32_t v00 = grid[p][a * w + b], v10 = grid[p][(a + 1) * w + b];
        const std::uint32_t v11 = grid[p][(a + 1) * w + b + 1], v01 = grid[p][a * w + b + 1];
        for (const Tri& t : {Tri{v00, v10, v11}, Tri{v00, v11, v01}}) {
          if (degenerate(verts, t, area_eps)) {
            ++dropped;
            continue;
          }
          tris.push_back(t);
          tri_patch.push_back(static_cast<std::uint32_t>(p));
        }
      }
  return {std::move(verts), std::move(tris), std::move(tri_patch), dropped, diag, area_eps};
}

}  // namespace raster::tools
