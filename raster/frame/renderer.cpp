// raster's own renderer behind the renderer seam.
#include "raster/frame/renderer.h"

#include "raster/frame/render.h"

namespace raster {

void RasterRenderer::render_into(const Scene& scene, const RenderOptions& options, RenderResult& result) const {
    raster::render_into(scene, options, result);
}

}  // namespace raster
