// The tiled renderer's binning: the frame in 64x64-pixel tiles, each with the setups that may cover one of its
// samples, in draw order; and the range of an edge function over a pixel rectangle that binning and the 8x8
// block tests both use.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "raster/pipeline/frame_params.h"
#include "raster/pipeline/setup.h"

namespace raster {

inline constexpr int kTileSize = 64;  // pixels per tile side
inline constexpr int kBlockSize = 8;  // pixels per block side for the hierarchical accept/reject

// Smallest and largest value of edge i of `t` (bias included) over the sample positions of the pixel rectangle
// [x0, x1] x [y0, y1] (inclusive), which lie in [x0 << F + extent.min_x, x1 << F + extent.max_x] and likewise in
// y: the edge function is affine, so its extremes are at the corners of that box.
struct EdgeRange {
    int64_t min, max;
};
inline EdgeRange edge_range(const TriangleSetup& t, int i, int x0, int x1, int y0, int y1, int fixed_bits,
                            const SampleExtent& extent) {
    const int64_t lo_x = (int64_t{x0} << fixed_bits) + extent.min_x, hi_x = (int64_t{x1} << fixed_bits) + extent.max_x;
    const int64_t lo_y = (int64_t{y0} << fixed_bits) + extent.min_y, hi_y = (int64_t{y1} << fixed_bits) + extent.max_y;
    const int64_t base = t.c[i] + t.bias[i];
    const int64_t ax_lo = t.a[i] * lo_x, ax_hi = t.a[i] * hi_x, by_lo = t.b[i] * lo_y, by_hi = t.b[i] * hi_y;
    return {base + std::min(ax_lo, ax_hi) + std::min(by_lo, by_hi), base + std::max(ax_lo, ax_hi) + std::max(by_lo, by_hi)};
}

// The tiles of the frame and, for each, the indices of the setups that may cover one of its samples.
struct TileBins {
    int tiles_x = 0, tiles_y = 0;
    std::vector<std::vector<uint32_t>>& setups;  // per tile, row by row; the workspace's lists, reused frame to frame
};

// Bins every setup to the tiles of its bounding box that no edge keeps entirely outside.
TileBins bin_setups(const std::vector<TriangleSetup>& setups, const FrameParams& frame,
                    std::vector<std::vector<uint32_t>>& lists);

}  // namespace raster
