// The reference backend: the reference rasterizer over the whole frame into the visibility buffer, then shading and
// resolve of every pixel. What the tiled backend must equal byte for byte.
#pragma once

#include "raster/frame/raster_backend.h"

namespace raster {

// Fills result.visibility whether or not the frame keeps it: the visibility buffer is how this backend works.
class ReferenceBackend final : public RasterBackend {
public:
    OpaqueDrawStats draw_opaque(const OpaqueDraw& draw, RenderResult& result) const override;
    void draw_depth(const FrameParams& frame, RenderWorkspace& workspace, float* view_depth) const override;
};

}  // namespace raster
