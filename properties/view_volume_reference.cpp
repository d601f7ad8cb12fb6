// The homogeneous coverage test and the double-precision clipping scale.
#include "properties/view_volume_reference.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/geometric.hpp>

namespace raster::properties {

HomogeneousTriangle homogeneous_triangle(const ClipTriangle& triangle) {
    std::array<glm::dvec3, 3> vertices;
    for (size_t i = 0; i < 3; ++i) vertices[i] = {triangle.v[i].x, triangle.v[i].y, triangle.v[i].w};
    return homogeneous_triangle(vertices);
}

HomogeneousTriangle homogeneous_triangle(const std::array<glm::dvec3, 3>& vertices) {
    // The columns a, b, c are the vertices' (x, y, w); the inverse's rows are (b x c, c x a, a x b) / det.
    const glm::dvec3 &a = vertices[0], &b = vertices[1], &c = vertices[2];
    HomogeneousTriangle t;
    const glm::dvec3 bc = glm::cross(b, c), ca = glm::cross(c, a), ab = glm::cross(a, b);
    const double det = glm::dot(a, bc);
    const double scale = glm::length(a) * glm::length(b) * glm::length(c);
    if (!std::isfinite(det) || !(std::fabs(det) > 1e-12 * scale)) return t;
    t.degenerate = false;
    t.rows = {bc / det, ca / det, ab / det};
    return t;
}

RayHit hit(const HomogeneousTriangle& t, const glm::dvec2& ndc) {
    const glm::dvec3 s(ndc, 1.0);
    const glm::dvec3 u(glm::dot(t.rows[0], s), glm::dot(t.rows[1], s), glm::dot(t.rows[2], s));
    const double sum = u.x + u.y + u.z;
    RayHit h;
    if (t.degenerate || !(sum > 0.0)) return h;
    h.bary = u / sum;
    h.w = 1.0 / sum;
    h.on_triangle = u.x >= 0.0 && u.y >= 0.0 && u.z >= 0.0;
    return h;
}

bool covers_in_volume(const HomogeneousTriangle& t, const ClipVolume& volume, const glm::dvec2& ndc) {
    const RayHit h = hit(t, ndc);
    return h.on_triangle && h.w >= volume.near && h.w <= volume.far;
}

double boundary_distance_px(const HomogeneousTriangle& t, const Frame& frame, const glm::dvec2& screen) {
    const glm::dvec3 s(ndc_of_screen(frame, screen), 1.0);
    // A linear function r . s of NDC, as a function of pixels: its gradient is (r.x 2/W, -r.y 2/H).
    auto distance = [&](const glm::dvec3& r, double value) {
        const double gx = r.x * 2.0 / frame.width, gy = -r.y * 2.0 / frame.height;
        const double gradient = std::hypot(gx, gy);
        return gradient > 0.0 ? std::fabs(value) / gradient : INFINITY;
    };
    double d = std::min({screen.x, frame.width - screen.x, screen.y, frame.height - screen.y});
    if (t.degenerate) return d;
    const glm::dvec3 sum_row = t.rows[0] + t.rows[1] + t.rows[2];
    const double sum = glm::dot(sum_row, s);
    // A sample whose w is the near or far plane's up to the double solve's rounding (relative 2^-30 allows condition
    // numbers up to 2^22) is on that boundary, even when the triangle's plane is parallel to it and the distance
    // below has no gradient (Regressions.triangleLyingInTheNearPlaneIsDrawnWhole).
    const double w = 1.0 / sum;
    for (const double plane : {double(frame.volume.near), double(frame.volume.far)})
        if (std::fabs(w - plane) <= std::ldexp(plane, -30)) return 0.0;
    for (const glm::dvec3& r : t.rows) d = std::min(d, distance(r, glm::dot(r, s)));
    // 1/w = sum(u) is linear in s, so w = near and w = far are lines too.
    return std::min({d, distance(sum_row, sum - 1.0 / frame.volume.near), distance(sum_row, sum - 1.0 / frame.volume.far)});
}

namespace {

double plane_distance(int plane, const glm::dvec4& p, const ClipVolume& v) {
    switch (plane) {
        case 0: return p.w - v.near;
        case 1: return v.far - p.w;
        case 2: return p.x + p.w;
        case 3: return p.w - p.x;
        case 4: return p.y + p.w;
        default: return p.w - p.y;
    }
}

double magnitude(const glm::dvec4& p) {
    return std::max({std::fabs(p.x), std::fabs(p.y), std::fabs(p.z), std::fabs(p.w)});
}

}  // namespace

ClippingScale clipping_scale(const ClipTriangle& triangle, const ClipVolume& volume) {
    std::vector<glm::dvec4> polygon;
    for (const glm::vec4& v : triangle.v) polygon.push_back(glm::dvec4(v));
    ClippingScale scale;
    for (int plane = 0; plane < 6 && !polygon.empty(); ++plane) {
        bool crossed = false;
        for (const glm::vec4& v : triangle.v) crossed |= plane_distance(plane, glm::dvec4(v), volume) < 0.0;
        if (!crossed) continue;
        std::vector<glm::dvec4> out;
        for (size_t i = 0; i < polygon.size(); ++i) {
            const glm::dvec4& p = polygon[i];
            const glm::dvec4& q = polygon[(i + 1) % polygon.size()];
            const double dp = plane_distance(plane, p, volume), dq = plane_distance(plane, q, volume);
            if (dp >= 0.0) {
                out.push_back(p);
                scale.largest = std::max(scale.largest, magnitude(p));
            }
            if ((dp >= 0.0) != (dq >= 0.0)) {
                const glm::dvec4 x = dp >= 0.0 ? p + (dp / (dp - dq)) * (q - p) : q + (dq / (dq - dp)) * (p - q);
                out.push_back(x);
                scale.largest = std::max(scale.largest, magnitude(x));
            }
        }
        polygon = out.size() >= 3 ? out : std::vector<glm::dvec4>{};
    }
    scale.count = static_cast<int>(polygon.size());
    scale.nearest = polygon.empty() ? 0.0 : INFINITY;
    for (const glm::dvec4& p : polygon) {
        scale.largest = std::max(scale.largest, magnitude(p));
        scale.nearest = std::min(scale.nearest, p.w);
    }
    return scale;
}

double clipped_coordinate_error(const ClippingScale& scale) { return std::ldexp(scale.largest, -18); }

}  // namespace raster::properties

