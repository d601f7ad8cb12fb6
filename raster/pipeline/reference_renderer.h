// The reference renderer: the front end, the reference rasterizer over the whole frame into the visibility buffer,
// then shading and resolve of every pixel. What the tiled renderer must equal byte for byte.
#pragma once

#include "raster/pipeline/frame.h"
#include "raster/pipeline/stages.h"

namespace raster {

// Renders the frame into `result`, reusing its buffers. Every stage of `stages` is used, reference_rasterize
// included; options.keep_visibility is ignored (the visibility buffer is how this renderer works).
void render_reference_into(const Scene& scene, const RenderOptions& options, const PipelineStages& stages,
                           RenderResult& result);

}  // namespace raster
