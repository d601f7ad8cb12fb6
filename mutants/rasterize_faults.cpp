// The reference rasterizer's faulty variants of the bug catalogue, each around the real rasterize_reference.
#include "mutants/rasterize_faults.h"

#include <cstdint>

#include <glm/vec3.hpp>

namespace raster::mutants {
namespace {

// Runs the real rasterizer with each setup's id replaced by its index, so every sample names its winning setup,
// then lets `resolve(setup, X, Y, pixel_x, pixel_y, fixed_bits, bary, view_depth)` write the sample's entry: the
// shape of a rasterizer whose coverage and depth test are right but whose resolve is faulty.
template <class Resolve>
void rasterize_with_resolve(const std::vector<TriangleSetup>& triangles, const FrameParams& params,
                            VisibilityBuffer& out, Resolve resolve) {
    std::vector<TriangleSetup> indexed = triangles;
    for (size_t i = 0; i < indexed.size(); ++i) indexed[i].triangle_id = static_cast<uint32_t>(i);
    rasterize_reference(indexed, params, out);
    const int fixed_bits = params.fixed_bits;
    const FixedSampleOffsets& offsets = params.fixed_offsets;
    for (int y = 0; y < out.height; ++y)
        for (int x = 0; x < out.width; ++x)
            for (int s = 0; s < out.samples; ++s) {
                const size_t at = out.index(x, y, s);
                if (out.triangle[at] == kNoTriangle) continue;
                const TriangleSetup& t = triangles[out.triangle[at]];
                const int64_t X = (int64_t{x} << fixed_bits) + offsets.x[s];
                const int64_t Y = (int64_t{y} << fixed_bits) + offsets.y[s];
                resolve(t, X, Y, x, y, fixed_bits, out.bary[at], out.view_depth[at]);
                out.triangle[at] = t.triangle_id;
            }
}

// Screen-space barycentrics E_i / area2 of a setup at (X, Y).
glm::dvec3 screen_barycentrics(const TriangleSetup& t, int64_t X, int64_t Y) {
    glm::dvec3 l;
    for (int i = 0; i < 3; ++i)
        l[i] = static_cast<double>(t.a[i] * X + t.b[i] * Y + t.c[i]) / static_cast<double>(t.area2);
    return l;
}

}  // namespace

// "affine instead of perspective-correct": attributes are interpolated linearly in screen space (every vertex
// weighted as if w were 1), so textures and colours swim and view depth is wrong.
void rasterize_affine(const std::vector<TriangleSetup>& triangles, const FrameParams& params, VisibilityBuffer& out) {
    std::vector<TriangleSetup> affine = triangles;
    for (TriangleSetup& t : affine) t.affine = true;  // the Interpolation::affine mode, forced
    rasterize_reference(affine, params, out);
}

// "depth buffer initialised with numeric_limits<float>::min()": with a conventional less-than test on
// d' = 1 - d (0 at near), the cleared value min() ~ 1e-38 is nearer than every surface, so nothing survives
// but fragments exactly on the near plane.
void rasterize_with_depth_cleared_to_min(const std::vector<TriangleSetup>& triangles, const FrameParams& params,
                                         VisibilityBuffer& out) {
    rasterize_reference(triangles, params, out);
    for (size_t i = 0; i < out.size(); ++i) {
        if (out.triangle[i] == kNoTriangle) continue;
        out.triangle[i] = kNoTriangle;  // 1 - d >= min() for every d < 1: the fragment fails "1 - d < min()"
        out.bary[i] = glm::vec3(0.0f);
        out.view_depth[i] = 0.0f;
    }
}

// "view depth interpolated linearly (w instead of 1/w)": the sample's w is the screen-space interpolation of the
// vertices' w, and the perspective weights l_i / w_i are scaled by it without renormalising, so the barycentrics
// no longer sum to 1 and the depth is too large inside the triangle.
void rasterize_with_linear_w(const std::vector<TriangleSetup>& triangles, const FrameParams& params,
                             VisibilityBuffer& out) {
    rasterize_with_resolve(triangles, params, out,
                           [](const TriangleSetup& t, int64_t X, int64_t Y, int, int, int, glm::vec3& bary, float& depth) {
                               const glm::dvec3 l = screen_barycentrics(t, X, Y);
                               double w = 0.0;
                               for (int i = 0; i < 3; ++i) w += l[i] / static_cast<double>(t.inv_w[i]);
                               glm::dvec3 b(0.0);
                               for (int i = 0; i < 3; ++i) b += l[i] * static_cast<double>(t.inv_w[i]) * w * glm::dvec3(t.bary[i]);
                               bary = glm::vec3(b);
                               depth = static_cast<float>(w);
                           });
}

// "barycentrics evaluated at the pixel centre": coverage is tested at each sample, but the attributes of every
// sample are interpolated at its pixel's centre, which may lie outside the triangle (negative barycentrics).
void rasterize_with_pixel_centre_barycentrics(const std::vector<TriangleSetup>& triangles, const FrameParams& params,
                                              VisibilityBuffer& out) {
    rasterize_with_resolve(triangles, params, out,
                           [](const TriangleSetup& t, int64_t, int64_t, int x, int y, int fixed_bits, glm::vec3& bary,
                              float& depth) {
                               const int64_t half = int64_t{1} << (fixed_bits - 1);
                               const glm::dvec3 l = screen_barycentrics(t, (int64_t{x} << fixed_bits) + half,
                                                                        (int64_t{y} << fixed_bits) + half);
                               double weight[3], total = 0.0;
                               for (int i = 0; i < 3; ++i) total += weight[i] = l[i] * static_cast<double>(t.inv_w[i]);
                               glm::dvec3 b(0.0);
                               for (int i = 0; i < 3; ++i) b += (weight[i] / total) * glm::dvec3(t.bary[i]);
                               bary = glm::vec3(b);
                               depth = static_cast<float>(1.0 / total);
                           });
}

// "no depth test (the first triangle drawn stays)": every fragment gets the same depth, so wherever triangles
// overlap the draw order decides, not the distance.
void rasterize_without_depth_test(const std::vector<TriangleSetup>& triangles, const FrameParams& params,
                                  VisibilityBuffer& out) {
    std::vector<TriangleSetup> flat = triangles;
    for (TriangleSetup& t : flat)
        for (double& d : t.depth) d = 0.5;
    rasterize_reference(flat, params, out);
}

}  // namespace raster::mutants
