// The clip stage's faulty variants of the bug catalogue, each a wrapper around the real clip_triangle.
#include "mutants/clip_faults.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace raster::mutants {

// "no near clipping": the side and far planes are clipped, the near plane is not, so vertices behind the eye
// (w <= 0) reach the divide.
ClippedPolygon clip_without_near(const glm::vec4& a, const glm::vec4& b, const glm::vec4& c, const ClipVolume& volume) {
    ClipVolume no_near = volume;
    no_near.near = -std::numeric_limits<float>::max();
    return clip_triangle(a, b, c, no_near);
}

// "triangles with w <= 0 dropped instead of clipped": any triangle reaching behind the near plane vanishes.
ClippedPolygon clip_dropping_near_crossers(const glm::vec4& a, const glm::vec4& b, const glm::vec4& c,
                                           const ClipVolume& volume) {
    if (a.w < volume.near || b.w < volume.near || c.w < volume.near) return {};
    return clip_triangle(a, b, c, volume);
}

// "side planes not clipped (vertices clamped instead)": only near and far cut the triangle; a vertex off screen
// reaches setup, which clamps it to the viewport border and so squashes the triangle. Emulated by clipping a copy
// whose x and y are scaled down by a power of two (exact) until no side plane can cut, then scaling back.
ClippedPolygon clip_without_side_planes(const glm::vec4& a, const glm::vec4& b, const glm::vec4& c,
                                        const ClipVolume& volume) {
    const double largest = std::max({std::fabs(a.x), std::fabs(a.y), std::fabs(b.x), std::fabs(b.y),
                                     std::fabs(c.x), std::fabs(c.y)});
    if (!std::isfinite(largest) || largest == 0.0) return clip_triangle(a, b, c, volume);
    int exponent = 0;
    std::frexp(largest / static_cast<double>(volume.near), &exponent);  // largest < near * 2^exponent
    const int shift = exponent + 1;                                       // so |x| * 2^-shift < near / 2 <= w / 2
    auto squeeze = [&](glm::vec4 p) {
        p.x = std::ldexp(p.x, -shift);
        p.y = std::ldexp(p.y, -shift);
        return p;
    };
    ClippedPolygon polygon = clip_triangle(squeeze(a), squeeze(b), squeeze(c), volume);
    for (int i = 0; i < polygon.count; ++i) {
        polygon.vertices[i].position.x = std::ldexp(polygon.vertices[i].position.x, shift);
        polygon.vertices[i].position.y = std::ldexp(polygon.vertices[i].position.y, shift);
    }
    return polygon;
}

// "near and far tested with a strict inequality": a vertex exactly on the near or far plane counts as outside,
// so a triangle touching a plane is clipped (new vertices, `clipped` set) instead of passed through untouched.
// In floats, w > near is exactly w >= nextafter(near, +inf).
ClippedPolygon clip_with_strict_near_far(const glm::vec4& a, const glm::vec4& b, const glm::vec4& c,
                                         const ClipVolume& volume) {
    ClipVolume strict = volume;
    strict.near = std::nextafter(volume.near, std::numeric_limits<float>::infinity());
    strict.far = std::nextafter(volume.far, 0.0f);
    return clip_triangle(a, b, c, strict);
}

// "NaN slips through the clip test": without the finiteness check, NaN compares false against every plane, so a
// triangle with a NaN coordinate has an empty outcode and goes to setup untouched.
ClippedPolygon clip_letting_nan_through(const glm::vec4& a, const glm::vec4& b, const glm::vec4& c,
                                        const ClipVolume& volume) {
    auto has_nan = [](const glm::vec4& p) {
        return std::isnan(p.x) || std::isnan(p.y) || std::isnan(p.z) || std::isnan(p.w);
    };
    if (!has_nan(a) && !has_nan(b) && !has_nan(c)) return clip_triangle(a, b, c, volume);
    ClippedPolygon polygon;
    polygon.count = 3;
    polygon.vertices[0] = {a, {1.0f, 0.0f, 0.0f}};
    polygon.vertices[1] = {b, {0.0f, 1.0f, 0.0f}};
    polygon.vertices[2] = {c, {0.0f, 0.0f, 1.0f}};
    return polygon;
}

}  // namespace raster::mutants
