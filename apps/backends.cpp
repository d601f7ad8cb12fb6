// The renderers the command line runs by name (backends.h).
#include "apps/backends.h"

#include "raster/core/errors.h"
#ifdef RASTER_WITH_GL
#include "backends/gl/gl_renderer.h"
#endif

namespace raster::cli {

std::unique_ptr<Renderer> renderer_named(const std::string& name) {
    if (name == "raster") return std::make_unique<RasterRenderer>();
    if (name == "gl") {
#ifdef RASTER_WITH_GL
        return std::make_unique<gl::GlRenderer>();
#else
        throw InputError("this raster was built without the GL backend (configure with -DRASTER_BUILD_GL=ON, which "
                         "needs libegl-dev and libgl-dev)");
#endif
    }
    throw InputError("no backend named '" + name + "' (raster or gl)");
}

}  // namespace raster::cli
