// The tiled production renderer: the frame in 64x64-pixel tiles, triangles binned to the tiles they touch, 8x8
// blocks trivially accepted or rejected (and skipped by hierarchical Z), each tile's sample planes kept in cache
// and shaded before the next tile.
#pragma once

#include "raster/frame/raster_backend.h"

namespace raster {

// Draws as ReferenceBackend does, with the same per-sample coverage, depth, barycentric and shading arithmetic
// (per_sample.h, resolve.h), so the image and the visibility buffer are byte-identical to the reference
// renderer's; only the memory order and the amount of work differ. The image is shaded the same way whether or not
// the visibility buffer is kept.
class TiledBackend final : public RasterBackend {
public:
    explicit TiledBackend(bool allow_simd) : allow_simd_(allow_simd) {}
    OpaqueDrawStats draw_opaque(const OpaqueDraw& draw, RenderResult& result) const override;
    void draw_depth(const FrameParams& frame, RenderWorkspace& workspace, float* view_depth) const override;

private:
    bool allow_simd_;
};

}  // namespace raster
