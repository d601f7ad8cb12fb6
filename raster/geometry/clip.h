// Clipping: homogeneous clipping of one triangle against the view volume, before any divide.
#pragma once

#include <array>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace raster {

// The planes, in clip space (w is the view depth, see conventions.h):
//   near   w >= near        far    w <= far
//   left   x >= -w          right  x <= w
//   bottom y >= -w          top    y <= w
// Near and far are tested on w itself rather than on z: the same planes, without the cancellation of w - z.
// An orthographic projection has w = 1 everywhere and the view depth in z (reversed-Z, 1 at near, 0 at far), so
// there near and far are z <= w and z >= 0.
struct ClipVolume {
    float near = 0.1f;
    float far = 100.0f;
    double side = 1.0;  // the side planes are x, y = +-side * w: 1 clips to the viewport, > 1 is a guard band
    bool orthographic = false;
};

// A clipped vertex: its clip-space position and its barycentric coordinates in the ORIGINAL triangle (clipping
// is linear in clip space, so these interpolate perspective-correctly like any attribute).
struct ClipVertex {
    glm::vec4 position;
    glm::vec3 bary;
};

// The barycentric coordinates of a triangle's own vertices a, b, c in it.
extern const std::array<glm::vec3, 3> kCornerBarycentrics;

// In exact arithmetic each plane adds at most one vertex to a convex polygon (3 + 6 = 9); rounding can make a
// sliver numerically non-convex, so there is room for more, and a polygon that would overflow is dropped.
inline constexpr int kMaxClippedVertices = 16;

// The clipped polygon: a convex fan of `count` vertices in the original winding; count is 0 when nothing is
// left. `clipped` is false when the triangle was entirely inside and is passed through untouched.
struct ClippedPolygon {
    int count = 0;
    bool clipped = false;
    std::array<ClipVertex, kMaxClippedVertices> vertices;  // only the first `count` are meaningful
};

// Clips a triangle. A triangle with any non-finite coordinate is rejected (count 0). Intersections are always
// computed from the inside vertex towards the outside one, so two triangles sharing an edge get bit-identical
// new vertices on it and stay watertight. After clipping every vertex has w >= near (> 0): no w <= 0 reaches
// a divide.
ClippedPolygon clip_triangle(const glm::vec4& a, const glm::vec4& b, const glm::vec4& c, const ClipVolume& volume);

// True when p is finite and inside every plane: clip_triangle passes a triangle of three such vertices through
// untouched, and only those.
bool inside_clip_volume(const glm::vec4& p, const ClipVolume& volume);

}  // namespace raster
