// The renderers the command line runs by name (--backend): raster itself, and the GL backend where it was built.
#pragma once

#include <memory>
#include <string>

#include "raster/frame/renderer.h"

namespace raster::cli {

// "raster" or "gl". Throws InputError for gl when this build has no GL backend (RASTER_BUILD_GL=OFF), and for any
// other name.
std::unique_ptr<Renderer> renderer_named(const std::string& name);

}  // namespace raster::cli
