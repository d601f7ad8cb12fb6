// The reference backend: the front end's chunks concatenated, the reference rasterizer, then shading and resolve
// over the visibility buffer.
#include "raster/frame/reference_renderer.h"

#include <limits>

#include "raster/core/stopwatch.h"
#include "raster/rasterize/reference_rasterizer.h"
#include "raster/resolve/resolve.h"

namespace raster {

OpaqueDrawStats ReferenceBackend::draw_opaque(const OpaqueDraw& draw, RenderResult& result) const {
    OpaqueDrawStats stats;
    auto stage_start = Clock::now();
    concatenate_setups(result.workspace.front_end.setup_chunks, draw.frame.threads, result.workspace.setups);
    rasterize_reference(result.workspace.setups, draw.frame, result.visibility);
    stats.ms_raster = milliseconds_since(stage_start);

    stage_start = Clock::now();
    resolve_image(result.visibility, draw.resolver, draw.frame.threads, result.image);
    stats.ms_shade = milliseconds_since(stage_start);
    for (uint32_t id : result.visibility.triangle) stats.covered_samples += id != kNoTriangle;
    return stats;
}

void ReferenceBackend::draw_depth(const FrameParams& frame, RenderWorkspace& workspace, float* view_depth) const {
    concatenate_setups(workspace.front_end.setup_chunks, frame.threads, workspace.setups);
    VisibilityBuffer visibility;
    rasterize_reference(workspace.setups, frame, visibility);
    for (size_t i = 0; i < visibility.size(); ++i)
        view_depth[i] =
            visibility.triangle[i] == kNoTriangle ? std::numeric_limits<float>::infinity() : visibility.view_depth[i];
}

}  // namespace raster
