// The GL backend: the scene drawn by OpenGL 4.5 on Mesa's EGL (llvmpipe on a machine without a GPU), with GLSL
// written from raster's conventions, its image and (asked for) its per-sample visibility read back. A second,
// independent rasterizer behind the renderer seam (raster/frame/renderer.h), which `raster render --backend gl`
// runs, `raster grade` judges by its image and `raster compare --backend gl` sample by sample.
#pragma once

#include <string>

#include "raster/frame/renderer.h"

namespace raster::gl {

class GlRenderer final : public Renderer {
public:
    // "gl (llvmpipe ..., 4.5 (Core Profile) Mesa ...)" once a frame has been drawn; "gl" before.
    std::string name() const override { return name_; }
    bool gives_visibility() const override { return true; }
    // Throws InputError when the scene asks for what the backend does not draw (unsupported_by_gl), for more
    // samples than the implementation has, or for the grid pattern; std::runtime_error when no context can be made.
    void render_into(const Scene& scene, const RenderOptions& options, RenderResult& result) const override;

private:
    mutable std::string name_ = "gl";
};

}  // namespace raster::gl
