// Coverage and depth: fixed-point edge functions per sample, a reversed-Z depth test, and the visibility buffer.
#pragma once

#include <vector>

#include <glm/vec2.hpp>

#include "raster/setup.h"
#include "raster/visibility_buffer.h"

namespace raster {

struct RasterParams {
    int width = 0;
    int height = 0;
    int snap_bits = 8;
    std::vector<glm::vec2> sample_offsets;  // from sample_pattern.h; their count is the samples per pixel
    int threads = 0;                        // 0 = all cores
};

// Rasterizes the triangles in order into `out` (resized to width x height x samples). For each sample the
// nearest triangle wins; on an exact depth tie the one drawn first stays. Then each visible sample gets its
// perspective-correct barycentrics in the original triangle and its view depth. The result is the same for any
// thread count: rows are split into bands and each band is processed by one thread, triangles in order.
void rasterize(const std::vector<TriangleSetup>& triangles, const RasterParams& params, VisibilityBuffer& out);

// The exact coverage test of one sample at fixed-point position (X, Y), shared by the rasterizer and its tests.
inline bool covers(const TriangleSetup& t, int64_t X, int64_t Y) {
    for (int i = 0; i < 3; ++i)
        if (t.a[i] * X + t.b[i] * Y + t.c[i] + t.bias[i] < 0) return false;
    return true;
}

}  // namespace raster
