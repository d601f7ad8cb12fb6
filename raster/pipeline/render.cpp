// The rasterizer's entry point: hands the frame to the renderer options.path names.
#include "raster/pipeline/render.h"

#include <stdexcept>

#include "raster/pipeline/reference_renderer.h"
#include "raster/pipeline/tiled_renderer.h"

namespace raster {

RenderResult render(const Scene& scene, const RenderOptions& options, const PipelineStages& stages) {
    RenderResult result;
    render_into(scene, options, result, stages);
    return result;
}

void render_into(const Scene& scene, const RenderOptions& options, RenderResult& result, const PipelineStages& stages) {
    if (options.path == RasterPath::reference) return render_reference_into(scene, options, stages, result);
    if (stages.reference_rasterize != PipelineStages{}.reference_rasterize)
        throw std::invalid_argument("a replaced reference_rasterize stage runs only on RasterPath::reference");
    render_tiled_into(scene, options, stages, result);
}

}  // namespace raster
