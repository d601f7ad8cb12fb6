// The view volume in double, independently of raster/geometry/clip.cpp: which samples a clip-space triangle covers inside
// the volume, found without clipping (2D homogeneous barycentrics, Olano & Greer 1997), how far each sample is from
// where that answer changes, and the scale of the numbers a float clipper works with.
#pragma once

#include <array>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "properties/stage_driver.h"

namespace raster::properties {

// A clip-space triangle as three linear functions of the homogeneous NDC point s = (x, y, 1): u_i(s) = row_i . s.
// The ray through s meets the triangle's plane at barycentrics u / (u0 + u1 + u2) and view depth w = 1 / sum(u);
// the point is on the triangle and in front of the eye exactly when sum(u) > 0 and every u_i >= 0.
struct HomogeneousTriangle {
    bool degenerate = true;  // the plane passes through the eye (or the vertices are not independent)
    std::array<glm::dvec3, 3> rows{};
};
HomogeneousTriangle homogeneous_triangle(const ClipTriangle& triangle);
// The same from each vertex's (x, y, w) in double.
HomogeneousTriangle homogeneous_triangle(const std::array<glm::dvec3, 3>& vertices);

struct RayHit {
    bool on_triangle = false;  // in front of the eye and inside the triangle
    glm::dvec3 bary{0.0};
    double w = 0.0;
};
RayHit hit(const HomogeneousTriangle& t, const glm::dvec2& ndc);

// Does the triangle cover this NDC point inside the volume (near <= w <= far; the side planes are the frame)?
bool covers_in_volume(const HomogeneousTriangle& t, const ClipVolume& volume, const glm::dvec2& ndc);

// Distance in pixels from a sample to the nearest line where coverage can change: the lines through the
// triangle's edges, the lines where its plane crosses w = near and w = far, and the frame's border.
double boundary_distance_px(const HomogeneousTriangle& t, const Frame& frame, const glm::dvec2& screen);

// What a float clipper has to work with, from clipping the triangle in double in the clipper's plane order
// (near, far, left, right, bottom, top; only the planes some vertex is outside of):
struct ClippingScale {
    double largest = 0.0;   // the largest |x|, |y|, |z|, |w| among the vertices that each cut keeps or makes
    double nearest = 0.0;   // the smallest w of the clipped polygon (0 when nothing is left)
    int count = 0;          // vertices of the clipped polygon
};
ClippingScale clipping_scale(const ClipTriangle& triangle, const ClipVolume& volume);

// The bound on each coordinate's error in a float clipper's output, derived in clip_checks.h: 2^-18 largest.
double clipped_coordinate_error(const ClippingScale& scale);

}  // namespace raster::properties
