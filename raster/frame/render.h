// The rasterizer's public entry point and the frame's order, written once: a valid Scene in, its visibility buffer
// and image out, with statistics (at a resolution divisor d above 1 the visibility buffer and the statistics are
// the internal frame's, width/d x height/d, and the image is stretched to the scene's size). Whichever backend
// draws (options.path), the frame runs
//   front end (vertex stage, cull, clip, setup) -> shadow pass -> opaque raster -> resolve -> transparency pass.
#pragma once

#include "raster/frame/frame.h"
#include "raster/frame/raster_backend.h"
#include "raster/scene/scene.h"

namespace raster {

// Renders the scene on the backend options.path names. The scene must be valid (the loaders validate;
// scene/validation.h).
RenderResult render(const Scene& scene, const RenderOptions& options);

// The same, reusing the buffers of a previous result (as a real-time renderer reuses its framebuffers), so a
// sequence of frames does not pay for fresh memory each time.
void render_into(const Scene& scene, const RenderOptions& options, RenderResult& result);

// The frame's order on a given backend, timing each stage into result.stats: what render_into runs, and the seam a
// test uses to run the same frame on a backend of its own (options.path and options.allow_simd are then not read).
void render_frame(const Scene& scene, const RenderOptions& options, const RasterBackend& backend,
                  RenderResult& result);

}  // namespace raster
