// The coverage reference, written from the definitions in conventions.h and nothing in raster/ but its constants.
#include "properties/reference/coverage_reference.h"

#include <cmath>

#include <glm/vec2.hpp>

#include "raster/core/conventions.h"

namespace raster::reference {

bool owns_edge(Point a, Point b, Point c) {
    if (a.y == b.y) return c.y > a.y;
    // c to the right of the edge's line, without division: for a downward edge (b.y > a.y) orient(a, b, c) < 0
    // means c is to the right (y down); for an upward edge the sign flips.
    const __int128 side = orient(a, b, c) * (b.y > a.y ? 1 : -1);
    return side < 0;
}

bool reference_covers(Point v0, Point v1, Point v2, Point p) {
    if (orient(v0, v1, v2) == 0) return false;
    const Point v[3] = {v0, v1, v2};
    for (int i = 0; i < 3; ++i) {
        const Point a = v[i], b = v[(i + 1) % 3], c = v[(i + 2) % 3];
        const __int128 sp = orient(a, b, p), sc = orient(a, b, c);
        if (sp == 0) {
            if (!owns_edge(a, b, c)) return false;
        } else if ((sp > 0) != (sc > 0)) {
            return false;
        }
    }
    return true;
}

bool reference_polygon_covers(const std::vector<Point>& polygon, Point p) {
    const size_t n = polygon.size();
    if (n < 3) return false;
    for (size_t i = 0; i < n; ++i) {
        // The next vertex after the edge is strictly on the interior side of a strictly convex polygon's edge.
        const Point a = polygon[i], b = polygon[(i + 1) % n], c = polygon[(i + 2) % n];
        const __int128 sp = orient(a, b, p), sc = orient(a, b, c);
        if (sc == 0) return false;
        if (sp == 0) {
            if (!owns_edge(a, b, c)) return false;
        } else if ((sp > 0) != (sc > 0)) {
            return false;
        }
    }
    return true;
}

bool on_open_segment(Point a, Point b, Point p) {
    if (orient(a, b, p) != 0 || p == a || p == b) return false;
    const __int128 along = static_cast<__int128>(p.x - a.x) * (b.x - a.x) + static_cast<__int128>(p.y - a.y) * (b.y - a.y);
    const __int128 length2 = static_cast<__int128>(b.x - a.x) * (b.x - a.x) + static_cast<__int128>(b.y - a.y) * (b.y - a.y);
    return along > 0 && along < length2;
}

int64_t snap_coordinate(double screen, int snap_bits) {
    const int fixed_bits = fixed_bits_for(snap_bits);
    const double snapped = std::floor(screen * std::ldexp(1.0, snap_bits) + 0.5);
    return static_cast<int64_t>(snapped) * (int64_t{1} << (fixed_bits - snap_bits));
}

namespace {

// The screen position of a clip-space vertex. The divide as a multiplication by 1/w in double, the same rounding as
// setup, so that no vertex lands on the other side of a half-way point by one double ulp.
glm::dvec2 screen_position(const glm::vec4& clip, int width, int height) {
    const double inv_w = 1.0 / static_cast<double>(clip.w);
    return {(static_cast<double>(clip.x) * inv_w + 1.0) * 0.5 * width,
            (1.0 - static_cast<double>(clip.y) * inv_w) * 0.5 * height};
}

// snap_coordinate clamped to [low, high], decided in double before any conversion to an integer.
int64_t clamped_snap_coordinate(double screen, int snap_bits, int64_t low, int64_t high) {
    const double fixed = std::floor(screen * std::ldexp(1.0, snap_bits) + 0.5) *
                         std::ldexp(1.0, fixed_bits_for(snap_bits) - snap_bits);
    if (!(fixed > static_cast<double>(low))) return low;  // NaN included
    if (!(fixed < static_cast<double>(high))) return high;
    return static_cast<int64_t>(fixed);
}

}  // namespace

Point snapped_vertex(const glm::vec4& clip, int width, int height, int snap_bits) {
    const glm::dvec2 screen = screen_position(clip, width, height);
    return {snap_coordinate(screen.x, snap_bits), snap_coordinate(screen.y, snap_bits)};
}

Point snapped_vertex(const glm::vec4& clip, int width, int height, int snap_bits, Point low, Point high) {
    const glm::dvec2 screen = screen_position(clip, width, height);
    return {clamped_snap_coordinate(screen.x, snap_bits, low.x, high.x),
            clamped_snap_coordinate(screen.y, snap_bits, low.y, high.y)};
}

int64_t snap_to_grid(double screen, int snap_bits, int fixed_bits) {
    return std::llround(screen * std::ldexp(1.0, snap_bits)) << (fixed_bits - snap_bits);
}

}  // namespace raster::reference
