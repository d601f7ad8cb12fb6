// The tiled production renderer: the frame in 64x64-pixel tiles, triangles binned to the tiles they touch, 8x8
// blocks trivially accepted or rejected (and skipped by hierarchical Z), each tile's sample planes kept in cache
// and shaded before the next tile.
#pragma once

#include "raster/pipeline/frame.h"
#include "raster/pipeline/setup_table.h"
#include "raster/pipeline/stages.h"

namespace raster {

// Renders like render_reference_into, with the same per-sample coverage, depth, barycentric and shading
// arithmetic (per_sample.h, resolve.h), so the image and the visibility buffer are byte-identical to the
// reference renderer's; only the memory order and the amount of work differ. Every stage of `stages` but
// reference_rasterize is used. With options.keep_visibility false, result.visibility is left empty (no
// full-frame sample planes at all), except in a scene with transparency, whose pass reads the opaque samples.
void render_tiled_into(const Scene& scene, const RenderOptions& options, const PipelineStages& stages,
                       RenderResult& result);

// The tiled renderer's coverage and depth alone, on setups made elsewhere (the properties draw hand-made
// triangles through it): the same binning, block tests, hierarchical Z (frame.hierarchical_z), traversal and
// visibility-buffer writes as render_tiled_into with keep_visibility, on frame.threads threads, coverage in SIMD
// unless allow_simd is false (the scalar fallback). Returns the number of (triangle, block) pairs hierarchical Z skipped.
size_t rasterize_tiled(const std::vector<TriangleSetup>& setups, const FrameParams& frame, bool allow_simd,
                       VisibilityBuffer& visibility);

// The same coverage and depth, keeping only each sample's view depth (+inf where no triangle covers it), in
// visibility-buffer order: what a depth-only pass (a shadow map's face) needs, without the visibility buffer. The
// setups are read where they are (SetupTable::of_chunks on a front end's chunks, or of_list).
void rasterize_depth_tiled(const SetupTable& setups, const FrameParams& frame, bool allow_simd, float* view_depth);

}  // namespace raster
