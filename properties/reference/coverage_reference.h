// The independent coverage reference: exact orientation tests in 128-bit integers on snapped vertices, with the
// top-left rule written from its definition, shared by the unit tests and the property suite.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/vec4.hpp>

namespace raster::reference {

// A point on the fixed-point grid of 1/2^fixed_bits pixel (screen space, y down).
struct Point {
    int64_t x = 0, y = 0;
    bool operator==(const Point&) const = default;
};

// cross(b - a, p - a), exactly. Inline: the raster fuzz target calls it for every sample of every triangle's box.
inline __int128 orient(Point a, Point b, Point p) {
    return static_cast<__int128>(b.x - a.x) * (p.y - a.y) - static_cast<__int128>(b.y - a.y) * (p.x - a.x);
}

// Is a sample on edge a-b owned by the triangle whose third vertex is c? (y down.) The triangle owns the edge
// when it is a top edge (horizontal, with c below it) or a left edge (not horizontal, with c to its right).
bool owns_edge(Point a, Point b, Point c);

// Does the triangle v0 v1 v2 (either winding) cover sample p under the top-left rule? Degenerate ones cover nothing.
bool reference_covers(Point v0, Point v1, Point v2, Point p);

// The same for a strictly convex polygon (no three consecutive vertices collinear), either winding.
bool reference_polygon_covers(const std::vector<Point>& polygon, Point p);

// Is p strictly inside segment a-b (on its line, between and distinct from its ends)?
bool on_open_segment(Point a, Point b, Point p);

// A screen coordinate snapped per conventions.h: floor(screen * 2^snap_bits + 0.5) (round half up), expressed in
// units of 1/2^fixed_bits pixel. Not clamped; callers keep vertices inside the viewport.
int64_t snap_coordinate(double screen, int snap_bits);

// Where a clip-space vertex lands after the divide, the viewport transform (NDC (-1, +1) -> screen (0, 0), y down)
// and snapping, for an image of width x height pixels. The vertex must have w > 0.
Point snapped_vertex(const glm::vec4& clip, int width, int height, int snap_bits);

// The same clamped per coordinate to [low, high] (fixed-point units), as setup clamps to the viewport or the guard
// band, for any vertex with w > 0: one that float clipping left far outside (or at infinity) lands on the bound, and
// a NaN coordinate on `low`.
Point snapped_vertex(const glm::vec4& clip, int width, int height, int snap_bits, Point low, Point high);

// The older form kept for the unit tests: round to nearest on the snap grid (away from zero at halves).
int64_t snap_to_grid(double screen, int snap_bits, int fixed_bits);

}  // namespace raster::reference
