// Setup: viewport transform, snapping, winding, edge equations with the top-left bias, and the bounding box.
#include "raster/geometry/setup.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "raster/geometry/camera_rays.h"
#include "raster/core/conventions.h"

namespace raster {
namespace {

// True when the directed edge (dx, dy) is a top or left edge for a triangle with E > 0 inside (y down).
bool is_top_left(int64_t dx, int64_t dy) { return dy < 0 || (dy == 0 && dx > 0); }

// Snaps a screen coordinate to 1/2^snap_bits of a pixel (round half up), expresses it in units of
// 1/2^fixed_bits, and clamps it to [low, high]: the viewport, or the guard band. The clip stage already keeps the
// coordinate inside up to rounding, so the clamp only absorbs float error and guarantees the overflow bound of
// conventions.h.
inline int64_t snap(double screen, double snap_scale, int shift, int64_t low, int64_t high) {
    const double scaled = std::floor(screen * snap_scale + 0.5);
    if (!(scaled > static_cast<double>(low >> shift))) return low;  // NaN included
    if (!(scaled < static_cast<double>(high >> shift))) return high;
    return std::clamp(static_cast<int64_t>(scaled) * (int64_t{1} << shift), low, high);  // may be < 0: no shift
}

// The classic float rasterizer's edge setup: the edge equation from float vertex coordinates, each product and
// the difference rounded to 24 bits, so two triangles sharing an edge can round it differently.
void round_edges_to_float(TriangleSetup& t) {
    for (int i = 0; i < 3; ++i) {
        const int s = (i + 1) % 3, e = (i + 2) % 3;
        const float xs = static_cast<float>(t.x[s]), ys = static_cast<float>(t.y[s]);
        const float dx = static_cast<float>(t.x[e]) - xs, dy = static_cast<float>(t.y[e]) - ys;
        t.a[i] = std::llround(static_cast<double>(-dy));
        t.b[i] = std::llround(static_cast<double>(dx));
        t.c[i] = std::llround(static_cast<double>(dy * xs - dx * ys));
    }
}

// The view depth an affine setup interpolates at a vertex: 1 / (1 / w), or an orthographic frame's, read from z.
double vertex_view_depth(const ScreenPoint& p, bool orthographic) {
    if (orthographic) return static_cast<double>(p.ortho_view_depth);
    return 1.0 / static_cast<double>(p.inv_w);
}

}  // namespace

double depth_key(double reversed_z, DepthFormat format) {
    switch (format) {
        case DepthFormat::float_z: return -static_cast<double>(static_cast<float>(1.0 - reversed_z));
        case DepthFormat::fixed24: return -(1.0 - reversed_z) * kFixed24Levels;
        default: return static_cast<double>(static_cast<float>(reversed_z));
    }
}

bool faces_front(const glm::vec4& a, const glm::vec4& b, const glm::vec4& c) {
    const double ax = a.x, ay = a.y, aw = a.w, bx = b.x, by = b.y, bw = b.w, cx = c.x, cy = c.y, cw = c.w;
    const double determinant = ax * (by * cw - bw * cy) - ay * (bx * cw - bw * cx) + aw * (bx * cy - by * cx);
    return determinant > 0.0;
}

SnapGrid snap_grid(const FrameParams& frame) {
    SnapGrid grid;
    const int64_t extent_x = int64_t{frame.width} << frame.fixed_bits;
    const int64_t extent_y = int64_t{frame.height} << frame.fixed_bits;
    // The snapped range: the viewport [0, extent], widened on each side by (side - 1) / 2 extents (guard band).
    const double margin = (frame.clip.side - 1.0) * 0.5;
    grid.low_x = -static_cast<int64_t>(margin * static_cast<double>(extent_x));
    grid.high_x = extent_x - grid.low_x;
    grid.low_y = -static_cast<int64_t>(margin * static_cast<double>(extent_y));
    grid.high_y = extent_y - grid.low_y;
    grid.snap_scale = static_cast<double>(int64_t{1} << frame.snap_bits);
    grid.shift = frame.fixed_bits - frame.snap_bits;
    return grid;
}

ScreenPoint project_to_screen(const glm::vec4& p, const FrameParams& frame, const SnapGrid& grid) {
    const double inv_w = 1.0 / static_cast<double>(p.w);  // w >= near > 0 after clipping
    const glm::dvec2 position =
        screen_from_ndc(static_cast<double>(p.x) * inv_w, static_cast<double>(p.y) * inv_w, frame.width, frame.height);
    const float ortho_view_depth =
        frame.clip.orthographic
            ? static_cast<float>(double(frame.clip.far) - double(p.z) * (double(frame.clip.far) - double(frame.clip.near)))
            : 0.0f;
    return {snap(position.x, grid.snap_scale, grid.shift, grid.low_x, grid.high_x),
            snap(position.y, grid.snap_scale, grid.shift, grid.low_y, grid.high_y),
            depth_key(static_cast<double>(p.z) * inv_w, frame.depth), static_cast<float>(inv_w), ortho_view_depth};
}

int setup_polygon(const ClippedPolygon& polygon, uint32_t triangle_id, const FrameParams& frame,
                  std::vector<TriangleSetup>& out) {
    if (polygon.count < 3) return 0;
    const SnapGrid grid = snap_grid(frame);
    ScreenPoint screen[kMaxClippedVertices];
    for (int i = 0; i < polygon.count; ++i) screen[i] = project_to_screen(polygon.vertices[i].position, frame, grid);
    int appended = 0;
    for (int k = 1; k + 1 < polygon.count; ++k)
        appended += setup_screen_triangle({&screen[0], &screen[k], &screen[k + 1]},
                                          {&polygon.vertices[0].bary, &polygon.vertices[k].bary,
                                           &polygon.vertices[k + 1].bary},
                                          triangle_id, frame, out);
    return appended;
}

int setup_screen_triangle(std::array<const ScreenPoint*, 3> v, std::array<const glm::vec3*, 3> bary,
                          uint32_t triangle_id, const FrameParams& frame, std::vector<TriangleSetup>& out) {
    const int fixed_bits = frame.fixed_bits;
    // Twice the signed area, cross(v1 - v0, v2 - v0), in screen space (y down): < 0 is front-facing (CCW in
    // NDC, see conventions.h).
    int64_t area2 = (v[1]->x - v[0]->x) * (v[2]->y - v[0]->y) - (v[1]->y - v[0]->y) * (v[2]->x - v[0]->x);
    if (area2 == 0) return 0;  // covers no sample under the fill rule
    if (area2 < 0) {
        std::swap(v[1], v[2]);
        std::swap(bary[1], bary[2]);
        area2 = -area2;
    }
    // Built in place: a TriangleSetup is some 300 bytes, and copying each one into `out` cost a seventh of
    // set-up on 80k-triangle meshes.
    TriangleSetup& setup = out.emplace_back();
    setup.triangle_id = triangle_id;
    setup.area2 = area2;
    setup.inv_area2 = 1.0 / static_cast<double>(area2);
    // An orthographic projection's w is 1: perspective correction is the identity, and the view depth is affine.
    setup.affine = frame.interpolation == Interpolation::affine || frame.clip.orthographic;
    setup.depth_fixed24 = frame.depth == DepthFormat::fixed24;
    for (int i = 0; i < 3; ++i) {
        setup.x[i] = v[i]->x;
        setup.y[i] = v[i]->y;
        setup.depth[i] = v[i]->depth;
        setup.inv_w[i] = v[i]->inv_w;
        if (setup.affine) setup.vertex_depth[i] = vertex_view_depth(*v[i], frame.clip.orthographic);
        setup.bary[i] = *bary[i];
    }
    for (int i = 0; i < 3; ++i) {
        // Edge opposite vertex i runs from vertex i+1 to vertex i+2: E(P) = cross(end - start, P - start).
        const int s = (i + 1) % 3, e = (i + 2) % 3;
        const int64_t dx = setup.x[e] - setup.x[s], dy = setup.y[e] - setup.y[s];
        setup.a[i] = -dy;
        setup.b[i] = dx;
        setup.c[i] = dy * setup.x[s] - dx * setup.y[s];
        setup.bias[i] = is_top_left(dx, dy) ? 0 : -1;
    }
    if (frame.edges == EdgeArithmetic::float32) round_edges_to_float(setup);
    const int64_t min_x = std::min({setup.x[0], setup.x[1], setup.x[2]});
    const int64_t max_x = std::max({setup.x[0], setup.x[1], setup.x[2]});
    const int64_t min_y = std::min({setup.y[0], setup.y[1], setup.y[2]});
    const int64_t max_y = std::max({setup.y[0], setup.y[1], setup.y[2]});
    // Samples sit at offsets in [0, 1) of their pixel, so pixel p can only hold a covered sample when
    // p <= max / 2^fixed_bits and p + 1 > min / 2^fixed_bits.
    setup.min_x = static_cast<int>(std::max<int64_t>(min_x >> fixed_bits, 0));
    setup.min_y = static_cast<int>(std::max<int64_t>(min_y >> fixed_bits, 0));
    setup.max_x = static_cast<int>(std::min<int64_t>(max_x >> fixed_bits, frame.width - 1));
    setup.max_y = static_cast<int>(std::min<int64_t>(max_y >> fixed_bits, frame.height - 1));
    if (setup.min_x > setup.max_x || setup.min_y > setup.max_y) {
        out.pop_back();
        return 0;
    }
    return 1;
}

}  // namespace raster
