// The per-sample arithmetic both rasterizers share, so that they agree bit for bit: the coverage test, the depth
// key and test, and the hit's barycentrics and view depth, and how a sample is written to the visibility buffer.
#pragma once

#include <cmath>
#include <cstdint>

#include <glm/vec3.hpp>

#include "raster/core/conventions.h"
#include "raster/geometry/setup.h"
#include "raster/rasterize/visibility_buffer.h"

namespace raster {

// The depth key of a covered sample (setup.h depth_key; larger is nearer), affine in screen space:
// d = d0 + (E1 (d1 - d0) + E2 (d2 - d0)) / area2, evaluated in double from the exact edge values so that every
// path (reference, tiled) gets the same float; a fixed24 key is rounded to its integer level first.
struct DepthPlane {
    double d0, d10_over_area, d20_over_area;
    bool fixed24;
    explicit DepthPlane(const TriangleSetup& t)
        : d0(t.depth[0]),
          d10_over_area((t.depth[1] - d0) / double(t.area2)),
          d20_over_area((t.depth[2] - d0) / double(t.area2)),
          fixed24(t.depth_fixed24) {}
    // The plane's value in double, before the key's rounding; e1 and e2 are exact edge values (bias removed).
    double value(int64_t e1, int64_t e2) const {
        return d0 + static_cast<double>(e1) * d10_over_area + static_cast<double>(e2) * d20_over_area;
    }
    // The key at a sample.
    float at(int64_t e1, int64_t e2) const {
        const double d = value(e1, e2);
        return static_cast<float>(fixed24 ? std::floor(d + 0.5) : d);
    }
};

// Where a visible sample is on its original triangle: perspective-correct barycentrics and view depth.
struct SampleHit {
    glm::vec3 bary;
    float view_depth;
};

// Screen-space barycentrics l_i = E_i / area2, perspective-corrected by 1/w (m_i = l_i / w_i, normalised), then
// mapped through the setup vertices' barycentrics in the original triangle; view depth = 1 / sum(l_i / w_i).
// An affine setup (Interpolation::affine) skips the correction: barycentrics l_i / sum(l), view depth
// sum(l_i w_i) / sum(l), both linear in screen space (sum(l) is 1 up to rounding with fixed edges, not with float
// ones). One division per sample: the area's reciprocal and the vertices' w come from setup.
inline SampleHit interpolate_hit(const TriangleSetup& t, int64_t X, int64_t Y) {
    double weight[3], total = 0.0, affine_depth = 0.0;
    for (int i = 0; i < 3; ++i) {
        const double l = static_cast<double>(t.a[i] * X + t.b[i] * Y + t.c[i]) * t.inv_area2;
        weight[i] = t.affine ? l : l * static_cast<double>(t.inv_w[i]);
        if (t.affine) affine_depth += l * t.vertex_depth[i];
        total += weight[i];
    }
    const double inv_total = 1.0 / total;
    glm::dvec3 bary(0.0);
    for (int i = 0; i < 3; ++i) bary += (weight[i] * inv_total) * glm::dvec3(t.bary[i]);
    return {glm::vec3(bary), static_cast<float>(t.affine ? affine_depth * inv_total : inv_total)};
}

// The exact coverage test of one sample at fixed-point position (X, Y), shared by the rasterizer and its tests.
inline bool covers(const TriangleSetup& t, int64_t X, int64_t Y) {
    for (int i = 0; i < 3; ++i)
        if (t.a[i] * X + t.b[i] * Y + t.c[i] + t.bias[i] < 0) return false;
    return true;
}

// The depth test, on planes of depth keys and winning setups: a covered sample takes the fragment when the sample
// is empty or the fragment is nearer (larger key); on an exact tie the earlier one stays.
struct DepthTestResult {
    bool written;     // the fragment won the sample
    bool was_empty;   // and the sample held nothing before
};
inline DepthTestResult depth_test(uint32_t* winner, float* depth, size_t at, float key, uint32_t index) {
    const bool empty = winner[at] == kNoTriangle;
    if (!empty && !(key > depth[at])) return {false, false};
    depth[at] = key;
    winner[at] = index;
    return {true, empty};
}

// Writes sample `at` of the visibility buffer: the scene triangle and where on it, or nothing.
inline void store_sample(VisibilityBuffer& out, size_t at, uint32_t triangle, const SampleHit& hit) {
    out.triangle[at] = triangle;
    out.bary[at] = hit.bary;
    out.view_depth[at] = hit.view_depth;
}
inline void store_empty_sample(VisibilityBuffer& out, size_t at) {
    out.triangle[at] = kNoTriangle;
    out.bary[at] = glm::vec3(0.0f);
    out.view_depth[at] = 0.0f;
}

}  // namespace raster
