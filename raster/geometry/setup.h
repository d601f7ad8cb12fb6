// Setup: clipped polygon -> fixed-point triangles with edge functions, fill-rule bias and a clamped bounding box.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "raster/geometry/clip.h"
#include "raster/geometry/frame_params.h"
#include "raster/scene/precision_modes.h"
#include "raster/scene/scene.h"

namespace raster {

// One screen-space triangle, ready to rasterize. Coordinates are on the grid of 1/2^fixed_bits pixel.
// Edge i is the edge opposite vertex i; E_i(X, Y) = a[i] * X + b[i] * Y + c[i] is > 0 inside, and equals
// area2 at vertex i, so E_i / area2 is vertex i's screen-space barycentric coordinate.
// A sample is covered when E_i + bias[i] >= 0 for all i (bias 0 on top-left edges, -1 elsewhere).
struct TriangleSetup {
    uint32_t triangle_id = 0;    // the original scene triangle
    int64_t x[3] = {}, y[3] = {};  // snapped vertices, wound so that E > 0 inside
    int64_t a[3] = {}, b[3] = {}, c[3] = {};
    int64_t bias[3] = {};
    int64_t area2 = 0;           // twice the snapped area, > 0
    double inv_area2 = 0.0;      // 1 / area2
    int min_x = 0, min_y = 0, max_x = -1, max_y = -1;  // pixel bounding box, inclusive, inside the viewport
    double depth[3] = {};        // the depth test's key at each vertex, larger is nearer (depth_key)
    float inv_w[3] = {};         // 1 / view depth at each vertex
    double vertex_depth[3] = {}; // affine setups only: view depth at each vertex (1 / inv_w; orthographic: from z)
    glm::vec3 bary[3];           // each vertex's barycentric coordinates in the original triangle
    bool affine = false;         // Interpolation::affine or an orthographic camera: barycentrics linear on screen
    bool depth_fixed24 = false;  // DepthFormat::fixed24: the interpolated key is rounded to an integer
};

// The depth test's key for reversed-Z depth d = z/w (near 1, far 0), in `format`; larger is always nearer, so
// every path keeps one comparison:
//   reversed_z  d rounded to float;
//   float_z     -(1 - d) rounded to float (OpenGL-style z in [0, 1], negated);
//   fixed24     -(1 - d) (2^24 - 1), not rounded: the interpolated value is rounded to an integer per sample.
inline constexpr double kFixed24Levels = 16777215.0;
double depth_key(double reversed_z, DepthFormat format);

// A vertex after the divide and the viewport transform: snapped to frame.snap_bits on the 1/2^fixed_bits grid,
// its depth key, and 1 / w; for an orthographic camera (w = 1) also its view depth, far - z (far - near).
struct ScreenPoint {
    int64_t x, y;
    double depth;
    float inv_w;
    float ortho_view_depth = 0.0f;
};

// The frame's snapping, formed once: the snapped range (the viewport, or the guard band) and the grid's scale.
struct SnapGrid {
    int64_t low_x = 0, high_x = 0, low_y = 0, high_y = 0;
    double snap_scale = 1.0;
    int shift = 0;
};
SnapGrid snap_grid(const FrameParams& frame);

// Projects a clip-space point with w > 0 to the screen: what setup_polygon does to each polygon vertex.
ScreenPoint project_to_screen(const glm::vec4& clip, const FrameParams& frame, const SnapGrid& grid);

// Sets up one screen triangle, its vertices v with their barycentrics in the original triangle, appending a setup
// to `out` unless it is degenerate or outside the viewport. Returns the number appended (0 or 1). setup_polygon
// runs it on each piece of the fan; the front end, on a triangle no clip plane touches, with its vertices
// projected once for every triangle that shares them.
int setup_screen_triangle(std::array<const ScreenPoint*, 3> v, std::array<const glm::vec3*, 3> bary,
                          uint32_t triangle_id, const FrameParams& frame, std::vector<TriangleSetup>& out);

// Projects, snaps (to frame.snap_bits, clamped to the viewport or to frame.clip's guard band) and triangulates a
// clipped polygon as a fan from its first vertex, in the frame's edge arithmetic, interpolation and depth format,
// appending one setup per non-degenerate triangle to `out` (back-face culling is faces_front's, before clipping).
// Returns the number appended.
int setup_polygon(const ClippedPolygon& polygon, uint32_t triangle_id, const FrameParams& frame,
                  std::vector<TriangleSetup>& out);

// Back-face culling is decided once per scene triangle, before clipping, from its clip-space vertices: the sign of
// det[x y w] (rows a, b, c) is that of the triangle's NDC area, and stays that of every part of it in front of the
// eye (clipped vertices are positive-winding combinations of a, b, c). > 0 is front-facing (counter-clockwise in
// NDC, see conventions.h). Deciding after snapping, per fan piece, would let a thin piece of a front face flip.
// Computed in double from float inputs: each 2x2 product is exact, so only 4 roundings remain.
bool faces_front(const glm::vec4& a, const glm::vec4& b, const glm::vec4& c);

}  // namespace raster
