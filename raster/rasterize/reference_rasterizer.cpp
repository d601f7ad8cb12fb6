// The reference rasterizer: band-parallel traversal of each triangle's bounding box with incremental 64-bit edge
// functions, then a pass that turns each winning sample into original-triangle barycentrics.
#include "raster/rasterize/reference_rasterizer.h"

#include <algorithm>
#include <cstdint>

#include "raster/core/conventions.h"
#include "raster/core/parallel.h"
#include "raster/geometry/camera_rays.h"
#include "raster/rasterize/per_sample.h"
#include "raster/geometry/sample_pattern.h"

namespace raster {
namespace {

constexpr int kBandRows = 16;

// While the depth pass runs, the visibility buffer's own planes hold its state: `triangle` holds the index of
// the winning setup and `view_depth` the reversed-Z depth of the winner. The resolve pass then overwrites both
// with the scene triangle id and the view depth, so no extra full-frame planes are allocated.
struct DepthPlanes {
    uint32_t* winner;
    float* depth;
};

// Rasterizes every triangle that touches rows [row_begin, row_end) into the depth planes. With one sample per
// pixel the edge functions are stepped at the sample itself; with several, each sample adds its own constant
// to the pixel corner's value.
template <bool kSingleSample>
void rasterize_band(const std::vector<TriangleSetup>& triangles, int row_begin, int row_end, int width,
                    int fixed_bits, const FixedSampleOffsets& offsets, DepthPlanes planes) {
    const int samples = static_cast<int>(offsets.x.size());
    std::vector<int64_t> sample_delta(static_cast<size_t>(samples) * 3);
    for (uint32_t index = 0; index < triangles.size(); ++index) {
        const TriangleSetup& t = triangles[index];
        if (t.max_y < row_begin || t.min_y >= row_end) continue;
        const int y0 = std::max(t.min_y, row_begin), y1 = std::min(t.max_y, row_end - 1);
        const DepthPlane depth(t);
        const int64_t step_x[3] = {t.a[0] << fixed_bits, t.a[1] << fixed_bits, t.a[2] << fixed_bits};
        // Edge values (bias included) at the first pixel's corner, or at its sample when there is only one.
        const int64_t first_x = (int64_t{t.min_x} << fixed_bits) + (kSingleSample ? offsets.x[0] : 0);
        const int64_t sample_y = kSingleSample ? offsets.y[0] : 0;
        if (!kSingleSample)
            for (int s = 0; s < samples; ++s)
                for (int i = 0; i < 3; ++i)
                    sample_delta[static_cast<size_t>(s) * 3 + i] = t.a[i] * offsets.x[s] + t.b[i] * offsets.y[s];
        for (int py = y0; py <= y1; ++py) {
            const int64_t row_y = (int64_t{py} << fixed_bits) + sample_y;
            int64_t e0 = t.a[0] * first_x + t.b[0] * row_y + t.c[0] + t.bias[0];
            int64_t e1 = t.a[1] * first_x + t.b[1] * row_y + t.c[1] + t.bias[1];
            int64_t e2 = t.a[2] * first_x + t.b[2] * row_y + t.c[2] + t.bias[2];
            size_t at = (static_cast<size_t>(py) * static_cast<size_t>(width) + static_cast<size_t>(t.min_x)) *
                        static_cast<size_t>(samples);
            for (int px = t.min_x; px <= t.max_x; ++px) {
                if (kSingleSample) {
                    if ((e0 | e1 | e2) >= 0)
                        depth_test(planes.winner, planes.depth, at, depth.at(e1 - t.bias[1], e2 - t.bias[2]), index);
                    ++at;
                } else {
                    for (int s = 0; s < samples; ++s, ++at) {
                        const int64_t* delta = &sample_delta[static_cast<size_t>(s) * 3];
                        const int64_t s0 = e0 + delta[0], s1 = e1 + delta[1], s2 = e2 + delta[2];
                        if ((s0 | s1 | s2) >= 0)
                            depth_test(planes.winner, planes.depth, at, depth.at(s1 - t.bias[1], s2 - t.bias[2]), index);
                    }
                }
                e0 += step_x[0];
                e1 += step_x[1];
                e2 += step_x[2];
            }
        }
    }
}

// Turns the winning setup of each sample in rows [row_begin, row_end) into the visibility buffer entry.
void resolve_band(const std::vector<TriangleSetup>& triangles, int row_begin, int row_end, int fixed_bits,
                  const FixedSampleOffsets& offsets, VisibilityBuffer& out) {
    const int samples = out.samples;
    size_t at = out.index(0, row_begin, 0);
    for (int py = row_begin; py < row_end; ++py) {
        for (int px = 0; px < out.width; ++px) {
            for (int s = 0; s < samples; ++s, ++at) {
                const uint32_t winner = out.triangle[at];
                if (winner == kNoTriangle) {
                    store_empty_sample(out, at);
                    continue;
                }
                const TriangleSetup& t = triangles[winner];
                const FixedPosition sample = sample_fixed_position(px, py, s, offsets, fixed_bits);
                store_sample(out, at, t.triangle_id, interpolate_hit(t, sample.x, sample.y));
            }
        }
    }
}

}  // namespace

void rasterize_reference(const std::vector<TriangleSetup>& triangles, const FrameParams& frame, VisibilityBuffer& out) {
    const int samples = frame.samples();
    out.resize(frame.width, frame.height, samples);
    const DepthPlanes planes{out.triangle.data(), out.view_depth.data()};
    const size_t bands = static_cast<size_t>((frame.height + kBandRows - 1) / kBandRows);
    parallel_for(bands, frame.threads, [&](size_t band) {
        const int row_begin = static_cast<int>(band) * kBandRows;
        const int row_end = std::min(frame.height, row_begin + kBandRows);
        if (samples == 1)
            rasterize_band<true>(triangles, row_begin, row_end, frame.width, frame.fixed_bits, frame.fixed_offsets, planes);
        else
            rasterize_band<false>(triangles, row_begin, row_end, frame.width, frame.fixed_bits, frame.fixed_offsets, planes);
        resolve_band(triangles, row_begin, row_end, frame.fixed_bits, frame.fixed_offsets, out);
    });
}

}  // namespace raster
