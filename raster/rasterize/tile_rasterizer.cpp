// The tiled rasterizer: per-tile sample planes, 8x8 block accept/reject with hierarchical Z, the tile loop, and the
// read-outs into a visibility buffer or a depth-only plane.
#include "raster/rasterize/tile_rasterizer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "raster/core/parallel.h"
#include "raster/core/stopwatch.h"
#include "raster/rasterize/coverage_kernels.h"
#include "raster/rasterize/depth_kernels.h"

namespace raster {
namespace {

// Hierarchical Z: for each 8x8 block of the tile, the smallest depth key stored in it (-inf while
// any sample may be empty). A triangle whose key cannot exceed that bound anywhere in the block loses every depth
// test there (ties keep the earlier triangle), so the block is skipped: the output never changes, only the work.
constexpr double kNoBound = -std::numeric_limits<double>::infinity();

// How far a sample's key can sit above the plane's double value at the block's corners: the plane's evaluation in
// double and the key's rounding to float (2^-24 relative) stay well inside a relative 2^-22; fixed24 rounds to the
// nearest level, up to half a level more.
inline double key_rounding_margin(double key, bool fixed24) {
    return std::fabs(key) * 0x1p-22 + (fixed24 ? 0.5 : 0.0) + 1e-300;
}

// The largest value of a triangle's depth plane over the sample positions of a pixel rectangle: the plane is
// affine, so it is at one of the rectangle's corners (extrapolated beyond the triangle, which only raises it).
inline double max_key_over(const TriangleSetup& t, const DepthPlane& depth, int x0, int x1, int y0, int y1, int F,
                           const SampleExtent& extent) {
    const int64_t xs[2] = {(int64_t{x0} << F) + extent.min_x, (int64_t{x1} << F) + extent.max_x};
    const int64_t ys[2] = {(int64_t{y0} << F) + extent.min_y, (int64_t{y1} << F) + extent.max_y};
    double largest = -std::numeric_limits<double>::infinity();
    for (int64_t X : xs)
        for (int64_t Y : ys)
            largest = std::max(largest, depth.value(t.a[1] * X + t.b[1] * Y + t.c[1], t.a[2] * X + t.b[2] * Y + t.c[2]));
    return largest;
}

// Samples of the block at (block_x0, block_y0) inside the image.
inline uint32_t block_samples(const TileJob& job, int block_x0, int block_y0) {
    return static_cast<uint32_t>((std::min(block_x0 + kBlockSize, job.width) - block_x0) *
                                 (std::min(block_y0 + kBlockSize, job.height) - block_y0) * job.samples);
}

// The smallest stored key of a block whose samples are all covered: a triangle whose key nowhere exceeds it loses
// every depth test in the block. Eight independent running minima, so the loop vectorizes without reassociating.
inline double block_min_key(const TileJob& job, const TileScratch& scratch, int block_x0, int block_y0, int tile_x,
                            int tile_y) {
    constexpr int kLanes = 8;
    const int S = job.samples;
    const size_t n = static_cast<size_t>(std::min(block_x0 + kBlockSize, job.width) - block_x0) * S;
    float lane[kLanes];
    std::fill(lane, lane + kLanes, std::numeric_limits<float>::infinity());
    for (int py = block_y0; py < std::min(block_y0 + kBlockSize, job.height); ++py) {
        const float* depth =
            scratch.depth.data() + (static_cast<size_t>(py - tile_y) * kTileSize + static_cast<size_t>(block_x0 - tile_x)) * S;
        size_t j = 0;
        for (; j + kLanes <= n; j += kLanes)
            for (int k = 0; k < kLanes; ++k) lane[k] = depth[j + k] < lane[k] ? depth[j + k] : lane[k];
        for (; j < n; ++j) lane[0] = depth[j] < lane[0] ? depth[j] : lane[0];
    }
    return static_cast<double>(*std::min_element(lane, lane + kLanes));
}

// Rasterizes one setup into the tile: its bounding box clipped to the tile, in 8x8-pixel blocks that are
// skipped when an edge keeps them entirely outside and taken whole when every edge keeps them inside. A partly
// covered block row's samples are found by the coverage kernel (coverage_kernels.h), SIMD when allowed.
void rasterize_in_tile(const TileJob& job, uint32_t ref, int tile_x, int tile_y, TileScratch& scratch,
                       bool allow_simd) {
    const TriangleSetup& t = job.setups[ref];
    const int F = job.fixed_bits, S = job.samples;
    const int x0 = std::max(t.min_x, tile_x), x1 = std::min(t.max_x, tile_x + kTileSize - 1);
    const int y0 = std::max(t.min_y, tile_y), y1 = std::min(t.max_y, tile_y + kTileSize - 1);
    // A block row reaches at most the box's width in pixels: a small triangle's rows need fewer offsets.
    const int row_pixels = std::min(kBlockSize, x1 - x0 + 1);
    for (int i = 0; i < 3; ++i) {
        // Sample s of pixel k along a block row: (a k << F) + the sample's own term, that term formed once per s.
        int64_t* offset = scratch.row_offset[i].data();
        for (int s = 0; s < S; ++s) offset[s] = t.a[i] * job.offsets.x[s] + t.b[i] * job.offsets.y[s] + t.bias[i];
        for (int k = row_pixels - 1; k >= 0; --k) {
            const int64_t pixel = t.a[i] * k << F;
            for (int s = 0; s < S; ++s) offset[static_cast<size_t>(k) * S + s] = pixel + offset[s];
        }
    }
    const DepthPlane depth(t);
    uint64_t* covered = scratch.row_covered.data();
    for (int by = y0; by <= y1; by = (by / kBlockSize + 1) * kBlockSize) {
        const int block_y1 = std::min(y1, (by / kBlockSize + 1) * kBlockSize - 1);
        for (int bx = x0; bx <= x1; bx = (bx / kBlockSize + 1) * kBlockSize) {
            const int block_x1 = std::min(x1, (bx / kBlockSize + 1) * kBlockSize - 1);
            bool reject = false, accept = true;
            for (int i = 0; i < 3; ++i) {
                const EdgeRange range = edge_range(t, i, bx, block_x1, by, block_y1, F, job.frame.extent);
                reject = reject || range.max < 0;
                accept = accept && range.min >= 0;
            }
            if (reject) continue;
            double* block_far = nullptr;
            uint32_t filled_before = 0, newly_filled = 0;
            const int block_x0 = bx / kBlockSize * kBlockSize, block_y0 = by / kBlockSize * kBlockSize;
            const size_t block = static_cast<size_t>((block_y0 - tile_y) / kBlockSize) * kBlocksPerTileSide +
                                 static_cast<size_t>((block_x0 - tile_x) / kBlockSize);
            if (job.frame.hierarchical_z) {
                block_far = &scratch.block_far[block];
                filled_before = scratch.block_filled[block];
                const double nearest = max_key_over(t, depth, bx, block_x1, by, block_y1, F, job.frame.extent);
                if (nearest + key_rounding_margin(nearest, depth.fixed24) <= *block_far) {  // all hidden
                    ++scratch.hidden_blocks;
                    continue;
                }
            }
            bool wrote = false;
            const size_t n = static_cast<size_t>(block_x1 - bx + 1) * S;
            const size_t words = coverage_words(n);
            if (accept) {
                std::fill(covered, covered + words, ~uint64_t{0});
                if (n % 64) covered[words - 1] = (uint64_t{1} << (n % 64)) - 1;
            }
            for (int py = by; py <= block_y1; ++py) {
                int64_t base[3];
                for (int i = 0; i < 3; ++i) base[i] = t.a[i] * (int64_t{bx} << F) + t.b[i] * (int64_t{py} << F) + t.c[i];
                if (!accept)
                    coverage_bits(base, scratch.row_offset[0].data(), scratch.row_offset[1].data(),
                                  scratch.row_offset[2].data(), n, covered, allow_simd);
                const size_t row_start = (static_cast<size_t>(py - tile_y) * kTileSize + static_cast<size_t>(bx - tile_x)) * S;
                const DepthRow row{depth, base[1] - t.bias[1], base[2] - t.bias[2], scratch.row_offset[1].data(),
                                   scratch.row_offset[2].data(), ref};
                const DepthRowResult tested = depth_test_row(row, covered, n, scratch.winner.data() + row_start,
                                                             scratch.depth.data() + row_start, allow_simd);
                wrote = wrote || tested.wrote;
                newly_filled += tested.newly_filled;
            }
            if (block_far && wrote) {
                // While any sample of the block is empty the bound stays -inf; once all are covered it is their minimum.
                const uint32_t filled = scratch.block_filled[block] = filled_before + newly_filled;
                if (filled == block_samples(job, block_x0, block_y0))
                    *block_far = block_min_key(job, scratch, block_x0, block_y0, tile_x, tile_y);
            }
        }
    }
}

int64_t nanoseconds_between(Clock::time_point from, Clock::time_point to) {
    return std::chrono::duration_cast<std::chrono::nanoseconds>(to - from).count();
}

}  // namespace

void rasterize_each_tile(const TileJob& job, const TileBins& bins, int threads, bool allow_simd, TileTimes& times,
                         const TileFinish& finish, const TileEmpty& empty) {
    const int samples = job.samples;
    parallel_for(bins.tiles(), threads, [&](size_t tile) {
        const auto tile_start = Clock::now();
        const int tile_x = static_cast<int>(tile % bins.tiles_x) * kTileSize;
        const int tile_y = static_cast<int>(tile / bins.tiles_x) * kTileSize;
        if (bins.tile_empty(tile)) {
            empty(tile_x, tile_y);
            times.shade_ns += nanoseconds_between(tile_start, Clock::now());
            return;
        }
        thread_local TileScratch scratch;
        // The planes, with room for the depth kernel's whole vectors past the last sample.
        const size_t plane = static_cast<size_t>(kTileSize) * kTileSize * samples + kDepthPadding;
        scratch.depth.resize(plane);
        // A tile that had triangles clears its winners after it is read out (or, when it threw before it could,
        // the next tile on the thread does).
        if (scratch.winner.size() != plane || scratch.winner_dirty) scratch.winner.assign(plane, kNoTriangle);
        const size_t row = static_cast<size_t>(kBlockSize) * samples + kCoveragePadding;
        for (auto& offset : scratch.row_offset) offset.resize(row);
        scratch.row_covered.resize(coverage_words(row));
        scratch.block_far.fill(kNoBound);
        scratch.block_filled.fill(0);
        scratch.hidden_blocks = 0;
        scratch.winner_dirty = true;
        // One setup behind the bins, so that the next setup's lines are on their way while this one is drawn: the
        // front end wrote them long before, and its first read was the tile loop's largest stall.
        uint32_t pending = kNoTriangle;
        bins.each_in_tile(tile, [&](uint32_t ref) {
            job.setups.prefetch(ref);
            if (pending != kNoTriangle) rasterize_in_tile(job, pending, tile_x, tile_y, scratch, allow_simd);
            pending = ref;
        });
        if (pending != kNoTriangle) rasterize_in_tile(job, pending, tile_x, tile_y, scratch, allow_simd);
        const auto finish_start = Clock::now();
        finish(tile_x, tile_y, scratch);
        std::fill(scratch.winner.begin(), scratch.winner.end(), kNoTriangle);
        scratch.winner_dirty = false;
        const auto tile_end = Clock::now();
        times.raster_ns += nanoseconds_between(tile_start, finish_start);
        times.shade_ns += nanoseconds_between(finish_start, tile_end);
    });
}

void store_tile_visibility(const TileJob& job, int tile_x, int tile_y, const TileScratch& scratch,
                           VisibilityBuffer& visibility) {
    const int S = job.samples;
    const int x1 = std::min(job.width, tile_x + kTileSize), y1 = std::min(job.height, tile_y + kTileSize);
    for (int py = tile_y; py < y1; ++py)
        for (int px = tile_x; px < x1; ++px)
            for (int s = 0; s < S; ++s) {
                const uint32_t winner = scratch.winner[tile_sample(px, py, s, tile_x, tile_y, S)];
                const size_t at = visibility.index(px, py, s);
                if (winner == kNoTriangle) store_empty_sample(visibility, at);
                else store_sample(visibility, at, job.setups[winner].triangle_id, hit_at(job, winner, px, py, s));
            }
}

void store_empty_tile(const TileJob& job, int tile_x, int tile_y, VisibilityBuffer& visibility) {
    const int x1 = std::min(job.width, tile_x + kTileSize), y1 = std::min(job.height, tile_y + kTileSize);
    for (int py = tile_y; py < y1; ++py)
        for (int px = tile_x; px < x1; ++px)
            for (int s = 0; s < job.samples; ++s) store_empty_sample(visibility, visibility.index(px, py, s));
}

size_t rasterize_tiled(const std::vector<TriangleSetup>& setups, const FrameParams& frame, bool allow_simd,
                       VisibilityBuffer& visibility) {
    const SetupTable table = SetupTable::of_list(setups);
    std::vector<BinGroup> lists;
    const TileBins bins = bin_setups(table, frame, frame.threads, lists);
    visibility.resize(frame.width, frame.height, frame.samples());
    const TileJob job{table, frame, frame.fixed_offsets, frame.fixed_bits, frame.width, frame.height, frame.samples()};
    std::atomic<size_t> hidden{0};
    TileTimes times;
    rasterize_each_tile(
        job, bins, frame.threads, allow_simd, times,
        [&](int tile_x, int tile_y, TileScratch& scratch) {
            store_tile_visibility(job, tile_x, tile_y, scratch, visibility);
            hidden += scratch.hidden_blocks;
        },
        [&](int tile_x, int tile_y) { store_empty_tile(job, tile_x, tile_y, visibility); });
    return hidden;
}

void rasterize_depth_tiled(const SetupTable& table, const FrameParams& frame, bool allow_simd,
                           std::vector<BinGroup>& lists, float* view_depth) {
    const TileBins bins = bin_setups(table, frame, frame.threads, lists);
    const int samples = frame.samples();
    const TileJob job{table, frame, frame.fixed_offsets, frame.fixed_bits, frame.width, frame.height, samples};
    constexpr float kEmpty = std::numeric_limits<float>::infinity();
    auto each_sample = [&](int tile_x, int tile_y, auto&& depth_of) {
        const int x1 = std::min(frame.width, tile_x + kTileSize), y1 = std::min(frame.height, tile_y + kTileSize);
        for (int py = tile_y; py < y1; ++py)
            for (int px = tile_x; px < x1; ++px)
                for (int s = 0; s < samples; ++s)
                    view_depth[sample_index(px, py, s, frame.width, samples)] = depth_of(px, py, s);
    };
    TileTimes times;
    rasterize_each_tile(
        job, bins, frame.threads, allow_simd, times,
        [&](int tile_x, int tile_y, TileScratch& scratch) {
            each_sample(tile_x, tile_y, [&](int px, int py, int s) {
                const uint32_t winner = scratch.winner[tile_sample(px, py, s, tile_x, tile_y, samples)];
                if (winner == kNoTriangle) return kEmpty;
                return hit_at(job, winner, px, py, s).view_depth;
            });
        },
        [&](int tile_x, int tile_y) { each_sample(tile_x, tile_y, [&](int, int, int) { return kEmpty; }); });
}

}  // namespace raster
