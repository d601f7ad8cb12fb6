// The rasterizer's public entry point: a valid Scene in, its visibility buffer and image out, with statistics.
// Which renderer draws the frame is options.path; both give the same bytes.
#pragma once

#include "raster/pipeline/frame.h"
#include "raster/pipeline/stages.h"
#include "raster/scene/scene.h"

namespace raster {

// Renders the scene. The scene must be valid (the loaders validate; scene/validation.h). `stages` are the real
// ones unless a test plants a faulty one. Throws std::invalid_argument when options.path is tiled and `stages`
// replaces reference_rasterize, which only the reference renderer runs.
RenderResult render(const Scene& scene, const RenderOptions& options, const PipelineStages& stages = {});

// The same, reusing the buffers of a previous result (as a real-time renderer reuses its framebuffers), so a
// sequence of frames does not pay for fresh memory each time.
void render_into(const Scene& scene, const RenderOptions& options, RenderResult& result,
                 const PipelineStages& stages = {});

}  // namespace raster
