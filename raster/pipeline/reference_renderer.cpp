// The reference renderer: front end, reference rasterizer, then shading and resolve over the visibility buffer.
#include "raster/pipeline/reference_renderer.h"

#include "raster/core/stopwatch.h"
#include "raster/pipeline/front_end.h"
#include "raster/pipeline/resolve.h"

namespace raster {

void render_reference_into(const Scene& scene, const RenderOptions& options, const PipelineStages& stages,
                           RenderResult& result) {
    const auto start = Clock::now();
    const FrontEnd front = run_front_end(scene, options, stages, result);
    RenderStats& stats = result.stats;

    auto stage_start = Clock::now();
    concatenate_setups(result.workspace.setup_chunks, front.frame.threads, result.workspace.setups);
    stages.reference_rasterize(result.workspace.setups, front.frame, result.visibility);
    stats.samples = result.visibility.size();
    stats.ms_raster = milliseconds_since(stage_start);

    const ShadowMaps shadows = build_shadow_maps(scene, front, options, stages, stats);
    stage_start = Clock::now();
    const Shader shader(scene, front.geometry, stages.lighting, &shadows);
    const ResolveParams resolve = resolve_params_for(scene, options);
    resolve_image(result.visibility, shader, resolve, result.image);
    stats.ms_shade = milliseconds_since(stage_start);
    composite_transparency_timed(scene, front, shader, resolve, result);

    for (uint32_t id : result.visibility.triangle) stats.covered_samples += id != kNoTriangle;
    stats.ms_total = milliseconds_since(start);
}

}  // namespace raster
