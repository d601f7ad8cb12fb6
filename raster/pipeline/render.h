// The rasterizer pipeline end to end: vertex stage -> clip -> setup -> coverage/depth -> visibility buffer ->
// shading and resolve -> image, with timings.
#pragma once

#include <chrono>
#include <cstdint>
#include <string>

#include "raster/image/image.h"
#include "raster/pipeline/stages.h"
#include "raster/pipeline/resolve.h"
#include "raster/scene/scene.h"
#include "raster/pipeline/visibility_buffer.h"

namespace raster {

// Which rasterizer runs: the tiled fast path (tiled_render.h) or the reference full-frame band rasterizer
// (rasterize.h). Both give byte-identical images and visibility buffers (tests/tiled_render_test.cpp).
enum class RasterPath { tiled, reference };

struct RenderOptions {
    int threads = 0;  // 0 = all cores; the output is the same for any value
    bool alpha = false;
    bool keep_visibility = true;  // the tiled path can skip filling the full-frame visibility buffer
    bool allow_simd = true;       // AVX2 where the CPU has it; false forces the portable code (same bytes)
    RasterPath path = RasterPath::tiled;  // a replaced rasterize stage (a test's mutant) always runs the reference
};

// Counts and in-process timings of one frame (loading excluded).
struct RenderStats {
    size_t triangles = 0;        // scene triangles in
    size_t clipped = 0;          // triangles that crossed a clip plane
    size_t rasterized = 0;       // screen triangles after clipping, fan splitting, culling and degeneracy
    size_t samples = 0;          // width * height * samples per pixel
    size_t covered_samples = 0;  // samples with a visible triangle
    size_t hidden_blocks = 0;    // tiled path: (triangle, 8x8 block) pairs skipped by hierarchical Z
    double ms_vertex = 0, ms_setup = 0, ms_raster = 0, ms_shade = 0, ms_total = 0;
};

// Per-frame buffers a renderer keeps in its result, so that render_into on the same result reuses their memory
// instead of paging in fresh memory every frame (tens of MB of triangle setups on an 80k-triangle mesh).
struct RenderWorkspace {
    std::vector<std::vector<TriangleSetup>> chunk_setups;
    std::vector<TriangleSetup> setups;
    std::vector<std::vector<uint32_t>> tile_bins;  // the tiled path's per-tile setup lists
};

struct RenderResult {
    VisibilityBuffer visibility;
    Image image;
    RenderStats stats;
    RenderWorkspace workspace;
};

// The front end every renderer shares: clips and sets up the vertex stage's triangles (in parallel chunks, kept
// in draw order) into workspace.setups, counting clipped and rasterized triangles into `stats`.
void set_up_triangles_into(const Scene& scene, const TransformedScene& geometry, int threads,
                           const PipelineStages& stages, RenderStats& stats, RenderWorkspace& workspace);
// The same into a fresh vector.
std::vector<TriangleSetup> set_up_triangles(const Scene& scene, const TransformedScene& geometry, int threads,
                                            const PipelineStages& stages, RenderStats& stats);

// The vertex stage every renderer runs first, counted and timed into `stats` (triangles, ms_vertex).
TransformedScene run_vertex_stage_timed(const Scene& scene, const PipelineStages& stages, RenderStats& stats);

// How the scene's settings and the options ask for samples to be resolved into pixels.
ResolveParams resolve_params_for(const Scene& scene, const RenderOptions& options);

// Milliseconds since `start`, for the stage timings.
double milliseconds_since(std::chrono::steady_clock::time_point start);

// Renders the scene. The scene must be valid (loaders validate; see scene/validation.h).
RenderResult render(const Scene& scene, const RenderOptions& options, const PipelineStages& stages = {});

// The same, reusing the buffers of a previous result (as a real-time renderer reuses its framebuffers), so a
// sequence of frames does not pay for fresh memory each time.
void render_into(const Scene& scene, const RenderOptions& options, RenderResult& result,
                 const PipelineStages& stages = {});

}  // namespace raster
