// Coverage and depth: band-parallel traversal of each triangle's bounding box with incremental 64-bit edge
// functions, then a pass that turns each winning sample into original-triangle barycentrics.
#include "raster/rasterize.h"

#include <algorithm>
#include <cstdint>

#include "raster/conventions.h"
#include "raster/parallel.h"
#include "raster/sample_pattern.h"

namespace raster {
namespace {

constexpr int kBandRows = 16;
constexpr uint32_t kNoSetup = 0xFFFFFFFFu;

// Per-frame scratch the depth test needs: the z-buffer and the index of the winning setup per sample.
struct DepthPlanes {
    std::vector<float> depth;
    std::vector<uint32_t> winner;
};

// Rasterizes every triangle that touches rows [row_begin, row_end) into the depth planes.
void rasterize_band(const std::vector<TriangleSetup>& triangles, int row_begin, int row_end, int width,
                    int fixed_bits, const FixedSampleOffsets& offsets, DepthPlanes& planes) {
    const int samples = static_cast<int>(offsets.x.size());
    std::vector<int64_t> sample_delta(static_cast<size_t>(samples) * 3);
    for (uint32_t index = 0; index < triangles.size(); ++index) {
        const TriangleSetup& t = triangles[index];
        if (t.max_y < row_begin || t.min_y >= row_end) continue;
        const int y0 = std::max(t.min_y, row_begin), y1 = std::min(t.max_y, row_end - 1);
        // Each edge function at a sample = its value at the pixel's corner + a per-sample constant.
        for (int s = 0; s < samples; ++s)
            for (int i = 0; i < 3; ++i)
                sample_delta[static_cast<size_t>(s) * 3 + i] = t.a[i] * offsets.x[s] + t.b[i] * offsets.y[s] + t.bias[i];
        const int64_t step_x[3] = {t.a[0] << fixed_bits, t.a[1] << fixed_bits, t.a[2] << fixed_bits};
        const double inv_area = 1.0 / static_cast<double>(t.area2);
        const double d0 = t.depth[0], d10 = double(t.depth[1]) - d0, d20 = double(t.depth[2]) - d0;
        const int64_t corner_x = int64_t{t.min_x} << fixed_bits;
        for (int py = y0; py <= y1; ++py) {
            const int64_t corner_y = int64_t{py} << fixed_bits;
            int64_t e[3];
            for (int i = 0; i < 3; ++i) e[i] = t.a[i] * corner_x + t.b[i] * corner_y + t.c[i];
            size_t base = (static_cast<size_t>(py) * static_cast<size_t>(width) + static_cast<size_t>(t.min_x)) *
                          static_cast<size_t>(samples);
            for (int px = t.min_x; px <= t.max_x; ++px, base += static_cast<size_t>(samples)) {
                for (int s = 0; s < samples; ++s) {
                    const int64_t* delta = &sample_delta[static_cast<size_t>(s) * 3];
                    const int64_t e0 = e[0] + delta[0], e1 = e[1] + delta[1], e2 = e[2] + delta[2];
                    if ((e0 | e1 | e2) < 0) continue;  // outside some edge (bias folded into delta)
                    // Depth is affine in screen space: d = d0 + l1 (d1 - d0) + l2 (d2 - d0), l_i = E_i / area2.
                    // The bias is -1 or 0, so e1 and e2 are the edge values within one unit; remove it again.
                    const double l1 = static_cast<double>(e1 - t.bias[1]) * inv_area;
                    const double l2 = static_cast<double>(e2 - t.bias[2]) * inv_area;
                    const float depth = static_cast<float>(d0 + l1 * d10 + l2 * d20);
                    const size_t at = base + static_cast<size_t>(s);
                    if (planes.winner[at] == kNoSetup || depth > planes.depth[at]) {
                        planes.depth[at] = depth;
                        planes.winner[at] = index;
                    }
                }
                for (int i = 0; i < 3; ++i) e[i] += step_x[i];
            }
        }
    }
}

// Turns the winning setup of each sample in rows [row_begin, row_end) into the visibility buffer entry.
void resolve_band(const std::vector<TriangleSetup>& triangles, int row_begin, int row_end, int fixed_bits,
                  const FixedSampleOffsets& offsets, const DepthPlanes& planes, VisibilityBuffer& out) {
    const int samples = out.samples;
    for (int py = row_begin; py < row_end; ++py) {
        for (int px = 0; px < out.width; ++px) {
            for (int s = 0; s < samples; ++s) {
                const size_t at = out.index(px, py, s);
                const uint32_t winner = planes.winner[at];
                if (winner == kNoSetup) continue;
                const TriangleSetup& t = triangles[winner];
                const int64_t X = (int64_t{px} << fixed_bits) + offsets.x[s];
                const int64_t Y = (int64_t{py} << fixed_bits) + offsets.y[s];
                // Screen-space barycentrics l_i, then perspective correction by 1/w: m_i = l_i / w_i.
                double weight[3], total = 0.0;
                for (int i = 0; i < 3; ++i) {
                    const double l = static_cast<double>(t.a[i] * X + t.b[i] * Y + t.c[i]) / static_cast<double>(t.area2);
                    weight[i] = l * static_cast<double>(t.inv_w[i]);
                    total += weight[i];
                }
                glm::dvec3 bary(0.0);
                for (int i = 0; i < 3; ++i) bary += (weight[i] / total) * glm::dvec3(t.bary[i]);
                out.triangle[at] = t.triangle_id;
                out.bary[at] = glm::vec3(bary);
                out.view_depth[at] = static_cast<float>(1.0 / total);
            }
        }
    }
}

}  // namespace

void rasterize(const std::vector<TriangleSetup>& triangles, const RasterParams& params, VisibilityBuffer& out) {
    const int samples = static_cast<int>(params.sample_offsets.size());
    out.resize(params.width, params.height, samples);
    const int fixed_bits = fixed_bits_for(params.snap_bits);
    const FixedSampleOffsets offsets = fixed_sample_offsets(params.sample_offsets, fixed_bits);
    DepthPlanes planes;
    planes.depth.assign(out.size(), 0.0f);
    planes.winner.assign(out.size(), kNoSetup);
    const size_t bands = static_cast<size_t>((params.height + kBandRows - 1) / kBandRows);
    parallel_for(bands, params.threads, [&](size_t band) {
        const int row_begin = static_cast<int>(band) * kBandRows;
        const int row_end = std::min(params.height, row_begin + kBandRows);
        rasterize_band(triangles, row_begin, row_end, params.width, fixed_bits, offsets, planes);
        resolve_band(triangles, row_begin, row_end, fixed_bits, offsets, planes, out);
    });
}

}  // namespace raster
