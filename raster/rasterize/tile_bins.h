// The tiled renderer's binning: the frame in 64x64-pixel tiles, each with the setups that may cover one of its
// samples, in draw order; and the range of an edge function over a pixel rectangle that binning and the 8x8
// block tests both use.
#pragma once

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

#include "raster/geometry/frame_params.h"
#include "raster/geometry/setup.h"
#include "raster/geometry/setup_table.h"

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

// A group of consecutive parts' setups binned to the frame's tiles: tile t's references are refs[first[t]] up to
// refs[first[t + 1]], in draw order. Kept in the workspace, so the lists' memory is reused frame to frame.
struct BinGroup {
    std::vector<uint32_t> first;                          // tiles + 1 offsets into refs
    std::vector<uint32_t> refs;                           // setup references (setup_table.h), tile by tile
    std::vector<std::pair<uint32_t, uint32_t>> touched;  // binning's scratch: (tile, reference) in draw order
};

// The tiles of the frame and, for each, the setups that may cover one of its samples: group by group of parts, each
// group's list in draw order, so the groups in order give the tile's setups in draw order.
struct TileBins {
    int tiles_x = 0, tiles_y = 0;
    const std::vector<BinGroup>& groups;
    // Calls fn(reference) for each setup binned to `tile`, in draw order.
    template <class Fn>
    void each_in_tile(size_t tile, Fn&& fn) const {
        for (const BinGroup& group : groups)
            for (uint32_t i = group.first[tile]; i < group.first[tile + 1]; ++i) fn(group.refs[i]);
    }
    bool tile_empty(size_t tile) const {
        for (const BinGroup& group : groups)
            if (group.first[tile] != group.first[tile + 1]) return false;
        return true;
    }
    size_t tiles() const { return static_cast<size_t>(tiles_x) * static_cast<size_t>(tiles_y); }
};

// How many groups of consecutive parts binning makes at most (fewer when the table has fewer parts).
inline constexpr size_t kBinGroups = 16;

// Bins every setup of `table` to the tiles of its bounding box that no edge keeps entirely outside, in groups of
// consecutive parts binned in parallel on `threads` threads, into `groups` (one BinGroup per group).
TileBins bin_setups(const SetupTable& table, const FrameParams& frame, int threads, std::vector<BinGroup>& groups);

}  // namespace raster
