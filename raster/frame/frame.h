// What one frame is asked for and what it gives back: the render options, the per-frame statistics, the buffers a
// renderer keeps between frames, and the result (visibility buffer and image).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "raster/image/image.h"
#include "raster/geometry/front_end.h"
#include "raster/geometry/setup.h"
#include "raster/rasterize/tile_bins.h"
#include "raster/rasterize/visibility_buffer.h"

namespace raster {

// Which raster backend draws the frame (raster_backend.h): the tiled production renderer (tiled_renderer.h) or the
// reference full-frame rasterizer it is checked against (reference_renderer.h). Both give the same bytes
// (tests/unit/frame/tiled_renderer_test.cpp).
enum class RasterPath { tiled, reference };

struct RenderOptions {
    int threads = 0;              // 0 = all cores; the output is the same for any value
    bool alpha = false;           // RGBA, alpha = covered fraction
    bool keep_visibility = true;  // the tiled renderer can skip filling the full-frame visibility buffer
    bool allow_simd = true;       // coverage on the CPU's best SIMD target; false: the scalar fallback (same bytes)
    RasterPath path = RasterPath::tiled;
};

// Counts and in-process timings of one frame (loading excluded).
struct RenderStats {
    size_t triangles = 0;        // scene triangles in
    size_t clipped = 0;          // triangles that crossed a clip plane
    size_t rasterized = 0;       // screen triangles after clipping, fan splitting, culling and degeneracy
    size_t samples = 0;          // width * height * samples per pixel (of the internal frame at a divisor above 1)
    size_t covered_samples = 0;  // samples with a visible triangle
    size_t hidden_blocks = 0;    // tiled renderer: (triangle, 8x8 block) pairs skipped by hierarchical Z
    // Wall time of each stage. The tiled renderer rasterizes and shades tile by tile, interleaved: its ms_raster
    // and ms_shade split that interleaved time in proportion to the time its threads spent in each.
    double ms_vertex = 0, ms_setup = 0, ms_raster = 0, ms_shade = 0, ms_total = 0;
    double ms_shadow = 0;  // rendering the shadow maps (their own vertex, setup and raster work), 0 without shadows
    double ms_transparency = 0;     // the transparency pass, 0 in an opaque scene
    double ms_upscale = 0;          // a reduced-resolution frame's upscale to the output size, 0 at resolution 1
    size_t transparent_fragments = 0;  // transparent fragments in front of the opaque surfaces
};

// Per-frame buffers a renderer keeps in its result, so that render_into on the same result reuses their memory
// instead of paging in fresh memory every frame.
struct RenderWorkspace {
    FrontEndSetups front_end;
    std::vector<TriangleSetup> setups;  // the reference renderer's: the front end's chunks concatenated
    std::vector<BinGroup> tile_bins;    // the tiled renderer's tile lists (tile_bins.h)
    // A reduced-resolution frame's (RenderSettings::resolution_divisor): its internal image and the upscale's rows.
    Image internal_image;
    std::vector<uint16_t> upscale_rows;
};

struct RenderResult {
    VisibilityBuffer visibility;
    Image image;
    RenderStats stats;
    RenderWorkspace workspace;
};

}  // namespace raster
