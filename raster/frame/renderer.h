// The renderer seam: what `raster render` runs a scene on and what `raster compare` judges. An implementation
// renders a frame (the image always; per-sample visibility where it can give it); the render job (render_job.h)
// writes it. raster's own renderer is RasterRenderer; another implementation (OpenGL, a plugin) goes behind the same
// seam and through the same job and comparison.
#pragma once

#include <string>

#include "raster/frame/frame.h"
#include "raster/scene/scene.h"

namespace raster {

class Renderer {
public:
    virtual ~Renderer() = default;
    // A short name for reports, e.g. "raster tiled".
    virtual std::string name() const = 0;
    // Whether render_into fills result.visibility when options.keep_visibility asks for it.
    virtual bool gives_visibility() const = 0;
    // Renders the valid scene into `result` (its buffers reused): result.image always, result.stats as far as the
    // renderer counts them, result.visibility when options.keep_visibility and gives_visibility(). Throws
    // InputError when the scene asks for more than the renderer's limits allow.
    virtual void render_into(const Scene& scene, const RenderOptions& options, RenderResult& result) const = 0;
};

// raster itself: render_into (render.h), on the backend options.path names.
class RasterRenderer final : public Renderer {
public:
    std::string name() const override { return "raster"; }
    bool gives_visibility() const override { return true; }
    void render_into(const Scene& scene, const RenderOptions& options, RenderResult& result) const override;
};

}  // namespace raster
