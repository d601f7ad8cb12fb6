// The fast path: the frame in 64x64-pixel tiles, triangles binned to the tiles they touch, 8x8-pixel blocks
// trivially accepted or rejected, each tile's sample planes kept in cache and shaded before the next tile.
#pragma once

#include "raster/pipeline/render.h"

namespace raster {

inline constexpr int kTileSize = 64;   // pixels per tile side
inline constexpr int kBlockSize = 8;   // pixels per block side for the hierarchical accept/reject

// Renders like render_into, with the same coverage, depth, barycentric and shading arithmetic, so the image and
// the visibility buffer are byte-identical to the reference path's; only the memory order and the amount of
// work differ. The rasterize stage of `stages` is not used (this is its replacement); every other stage is.
// With options.keep_visibility false, result.visibility is left empty (no full-frame sample planes at all).
void render_tiled_into(const Scene& scene, const RenderOptions& options, RenderResult& result,
                       const PipelineStages& stages = {});

}  // namespace raster
