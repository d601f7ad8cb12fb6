// Polygon triangulation for the mesh readers: quads by their shorter diagonal, larger polygons by ear clipping.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

namespace raster {

// One triangle of a polygon, as three indices into the polygon's corner list.
using PolygonTriangle = std::array<uint32_t, 3>;

// Appends the triangles of the polygon whose corners are `corners` (in order, at least 3) to `out`: always
// corners.size() - 2 of them, each with the polygon's winding, so no face is lost and culling sees the face as the
// file drew it. The choices it makes:
// - A triangle is kept as it is: (0, 1, 2).
// - A quad is split along its shorter diagonal, the distances compared in float exactly as tinyobjloader (the OBJ
//   reader raster used before its own) compared them: (0, 1, 2) (0, 2, 3) when corners 0 and 2 are strictly closer
//   than corners 1 and 3, else (0, 1, 3) (1, 2, 3), ties included. Like tinyobjloader it does not look at whether
//   the quad is concave, so OBJ files keep the triangles they always had.
// - A polygon of five or more corners is clipped in its own plane, the plane of its Newell normal (in double, so a
//   polygon tilted against every axis is not flattened onto one), which also orients it: seen from the normal the
//   corners run counter-clockwise. An ear is a corner that turns strictly left and whose triangle with its two
//   neighbours has no other corner inside or on its edges, where only corners that do not turn strictly left are
//   tested (only those can lie inside an ear) and corners at the same place as one of the ear's own are ignored
//   (a polygon may touch itself there). The search starts at corner 0 and goes on from the corner after each ear
//   clipped, so concave polygons are handled; once no corner is an ear (a self-intersecting polygon, or one that
//   rounding has made so), the rest is fanned from its first remaining corner.
// - A degenerate polygon, whose Newell normal is zero (every corner on one line or at one point), is fanned from
//   corner 0: its triangles have no area, but they keep the face's corners, as the file has them.
void triangulate_polygon(std::span<const glm::vec3> corners, std::vector<PolygonTriangle>& out);

}  // namespace raster
