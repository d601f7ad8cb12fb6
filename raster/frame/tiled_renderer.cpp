// The tiled backend: the tile rasterizer's planes read out tile by tile, each tile's pixels shaded and resolved while
// its planes are in cache, and its samples written to the visibility buffer when the frame keeps one.
#include "raster/frame/tiled_renderer.h"

#include <algorithm>
#include <atomic>

#include "raster/core/stopwatch.h"
#include "raster/rasterize/tile_rasterizer.h"
#include "raster/resolve/resolve.h"

namespace raster {
namespace {

// A worker's shading scratch: one pixel's triangle ids, and the tile's covered pixels waiting to be shaded together.
struct TileShading {
    std::vector<uint32_t> pixel_triangle;
    ResolveBatch batch;
};

// Shades the tile's pixels into the image; returns its covered samples. A sample's barycentrics are worked out only
// where the resolver shades it.
size_t resolve_tile(const TileJob& job, int tile_x, int tile_y, const PixelResolver& resolver,
                    const TileScratch& scratch, TileShading& shading, Image& image) {
    const int S = job.samples;
    const int x1 = std::min(job.width, tile_x + kTileSize), y1 = std::min(job.height, tile_y + kTileSize);
    size_t covered = 0;
    shading.pixel_triangle.resize(static_cast<size_t>(S));
    shading.batch.clear();  // nothing left from a tile that threw part-way
    for (int py = tile_y; py < y1; ++py) {
        for (int px = tile_x; px < x1; ++px) {
            const size_t first = tile_sample(px, py, 0, tile_x, tile_y, S);
            auto hit = [&](int s) { return hit_at(job, scratch.winner[first + s], px, py, s); };  // a covered sample
            // The common pixels, answered without per-sample bookkeeping.
            const uint32_t winner = scratch.winner[first];
            const bool uniform = is_uniform(&scratch.winner[first], S);
            if (uniform && winner == kNoTriangle) {  // and the empty pixels after it, written as one row
                int run_end = px + 1;
                auto empty_at = [&](int x) {
                    const uint32_t* w = &scratch.winner[first + static_cast<size_t>(x - px) * S];
                    return w[0] == kNoTriangle && is_uniform(w, S);
                };
                while (run_end < x1 && empty_at(run_end)) ++run_end;
                resolver.background_row(image.at(px, py), run_end - px);
                px = run_end - 1;
                continue;
            }
            if (uniform && resolver.shades_uniform_pixels_once()) {
                resolver.add_uniform(job.setups[winner].triangle_id, hit(0).bary, image.at(px, py), shading.batch);
                covered += static_cast<size_t>(S);
                continue;
            }
            for (int s = 0; s < S; ++s) {
                const uint32_t sample_winner = scratch.winner[first + s];
                shading.pixel_triangle[s] =
                    sample_winner == kNoTriangle ? kNoTriangle : job.setups[sample_winner].triangle_id;
                covered += sample_winner != kNoTriangle;
            }
            resolver.add_with(shading.pixel_triangle.data(), image.at(px, py), shading.batch,
                              [&](int s) { return hit(s).bary; });
        }
    }
    resolver.finish(shading.batch);
    return covered;
}

}  // namespace

OpaqueDrawStats TiledBackend::draw_opaque(const OpaqueDraw& draw, RenderResult& result) const {
    const FrameParams& frame = draw.frame;
    OpaqueDrawStats stats;
    auto stage_start = Clock::now();
    const SetupTable setups = SetupTable::of_chunks(result.workspace.front_end.setup_chunks);
    const TileBins bins = bin_setups(setups, frame, frame.threads, result.workspace.tile_bins);
    stats.ms_bin = milliseconds_since(stage_start);

    stage_start = Clock::now();
    const int samples = frame.samples();
    const PixelResolver& resolver = draw.resolver;
    Image& image = result.image;
    size_image(image, frame.width, frame.height, resolver.channels());
    VisibilityBuffer* visibility = nullptr;
    if (draw.keep_visibility) {
        result.visibility.resize(frame.width, frame.height, samples);
        visibility = &result.visibility;
    } else {
        result.visibility = VisibilityBuffer{};
    }
    const TileJob job{setups, frame, frame.fixed_offsets, frame.fixed_bits, frame.width, frame.height, samples};
    std::atomic<size_t> covered{0}, hidden{0};
    TileTimes times;
    rasterize_each_tile(
        job, bins, frame.threads, allow_simd_, times,
        [&](int tile_x, int tile_y, TileScratch& scratch) {
            thread_local TileShading shading;
            covered += resolve_tile(job, tile_x, tile_y, resolver, scratch, shading, image);
            if (visibility) store_tile_visibility(job, tile_x, tile_y, scratch, *visibility);
            hidden += scratch.hidden_blocks;
        },
        [&](int tile_x, int tile_y) {  // nothing drawn here: background only
            const int x1 = std::min(frame.width, tile_x + kTileSize), y1 = std::min(frame.height, tile_y + kTileSize);
            for (int py = tile_y; py < y1; ++py) resolver.background_row(image.at(tile_x, py), x1 - tile_x);
            if (visibility) store_empty_tile(job, tile_x, tile_y, *visibility);
        });
    stats.covered_samples = covered;
    stats.hidden_blocks = hidden;
    // Rasterization and shading are interleaved per tile: their wall time is split as their thread time is.
    const double interleaved_ms = milliseconds_since(stage_start);
    const double thread_ns = static_cast<double>(times.raster_ns + times.shade_ns);
    const double raster_share = thread_ns > 0.0 ? static_cast<double>(times.raster_ns.load()) / thread_ns : 1.0;
    stats.ms_raster = interleaved_ms * raster_share;
    stats.ms_shade = interleaved_ms - stats.ms_raster;
    return stats;
}

void TiledBackend::draw_depth(const FrameParams& frame, RenderWorkspace& workspace, float* view_depth) const {
    rasterize_depth_tiled(SetupTable::of_chunks(workspace.front_end.setup_chunks), frame, allow_simd_,
                          workspace.tile_bins, view_depth);
}

}  // namespace raster
