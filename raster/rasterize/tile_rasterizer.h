// The tiled rasterizer's coverage and depth: each tile's binned setups drawn in draw order into per-tile sample
// planes (depth key and winning setup per sample), in 8x8 blocks trivially accepted or rejected and skipped by
// hierarchical Z; what the planes hold is then read out by the caller, tile by tile, while they are in cache.
#pragma once

#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "raster/geometry/frame_params.h"
#include "raster/rasterize/per_sample.h"
#include "raster/geometry/setup_table.h"
#include "raster/rasterize/tile_bins.h"
#include "raster/rasterize/visibility_buffer.h"

namespace raster {

// Hierarchical Z keeps, for each 8x8 block of the tile, a bound on its stored depth keys (tile_rasterizer.cpp).
inline constexpr int kBlocksPerTileSide = kTileSize / kBlockSize;

// One worker's tile planes: depth and winning setup per sample (pixel by pixel, row by row, `samples` entries a
// pixel; tile_sample gives the index), and the per-triangle sample constants.
struct TileScratch {
    std::vector<float> depth;
    std::vector<uint32_t> winner;
    std::array<double, kBlocksPerTileSide * kBlocksPerTileSide> block_far;  // hierarchical Z bounds
    std::array<uint32_t, kBlocksPerTileSide * kBlocksPerTileSide> block_filled;  // non-empty samples per block
    size_t hidden_blocks = 0;                                               // blocks it skipped, this tile
    bool winner_dirty = false;  // `winner` holds a tile's triangles: cleared after the tile, or before the next
    // For the samples of one block row, j = pixel * samples + sample: each edge's offset from the edge value at
    // the row's first pixel corner (pixel * a << F + a * ox + b * oy + bias), and the covered samples' bits. Only
    // the pixels the current triangle's rows reach are written; the kernels mask the rest off.
    std::vector<int64_t> row_offset[3];
    std::vector<uint64_t> row_covered;
};

struct TileJob {
    const SetupTable& setups;  // the references in the bins and the winner planes name these
    const FrameParams& frame;
    const FixedSampleOffsets& offsets;  // frame.fixed_offsets
    int fixed_bits;                     // frame.fixed_bits
    int width, height, samples;         // frame.width, frame.height, frame.samples()
};

// Setup `ref`'s hit at sample s of pixel (px, py): what every read-out of a tile's winners interpolates.
inline SampleHit hit_at(const TileJob& job, uint32_t ref, int px, int py, int s) {
    const int F = job.fixed_bits;
    return interpolate_hit(job.setups[ref], (int64_t{px} << F) + job.offsets.x[s], (int64_t{py} << F) + job.offsets.y[s]);
}

// Where sample s of pixel (px, py) is in the planes of the tile whose upper-left pixel is (tile_x, tile_y).
inline size_t tile_sample(int px, int py, int s, int tile_x, int tile_y, int samples) {
    return (static_cast<size_t>(py - tile_y) * kTileSize + static_cast<size_t>(px - tile_x)) * samples + s;
}

// Thread time spent rasterizing tiles and reading them out (the caller's finish and empty).
struct TileTimes {
    std::atomic<int64_t> raster_ns{0}, shade_ns{0};
};

// finish(tile_x, tile_y, scratch): reads out a tile whose setups are drawn. empty(tile_x, tile_y): a tile no setup
// was binned to, whose planes are not touched.
using TileFinish = std::function<void(int tile_x, int tile_y, TileScratch& scratch)>;
using TileEmpty = std::function<void(int tile_x, int tile_y)>;

// The tile loop: every tile, in parallel on `threads` threads, gets its scratch planes reset and its binned setups
// rasterized in draw order (coverage in SIMD unless allow_simd is false), then finish reads the planes out; a tile
// without setups gets empty instead.
void rasterize_each_tile(const TileJob& job, const TileBins& bins, int threads, bool allow_simd, TileTimes& times,
                         const TileFinish& finish, const TileEmpty& empty);

// Writes every sample of the finished tile at (tile_x, tile_y) into `visibility`; store_empty_tile the samples of a
// tile nothing covers.
void store_tile_visibility(const TileJob& job, int tile_x, int tile_y, const TileScratch& scratch,
                           VisibilityBuffer& visibility);
void store_empty_tile(const TileJob& job, int tile_x, int tile_y, VisibilityBuffer& visibility);

// The coverage and depth alone, on setups made elsewhere (the properties draw hand-made triangles through it): the
// same binning, block tests, hierarchical Z (frame.hierarchical_z), traversal and visibility-buffer writes as the
// tiled backend's frame with its visibility kept, on frame.threads threads, coverage in SIMD unless allow_simd is
// false (the scalar fallback). Returns the number of (triangle, block) pairs hierarchical Z skipped.
size_t rasterize_tiled(const std::vector<TriangleSetup>& setups, const FrameParams& frame, bool allow_simd,
                       VisibilityBuffer& visibility);

// The same coverage and depth, keeping only each sample's view depth (+inf where no triangle covers it), in
// visibility-buffer order: what a depth-only pass (a shadow map's face) needs, without the visibility buffer. The
// setups are read where they are (SetupTable::of_chunks on a front end's chunks, or of_list); `bins` holds the
// tile lists.
void rasterize_depth_tiled(const SetupTable& setups, const FrameParams& frame, bool allow_simd,
                           std::vector<BinGroup>& bins, float* view_depth);

}  // namespace raster
