// raster's own clip, setup and reference rasterizer behind the plugin interface (raster_plugin.h), reading nothing
// but the frame it is handed: what a correct plugin answers. The renderer properties must pass on it, and through it
// the plugin backend's hand-over is checked against raster's own frames (tests/backends/plugin_backend_test.cpp).
#pragma once

#include <memory>

#include "backends/plugin/plugin_library.h"

namespace raster::properties {

// The plugin, named "raster's stages", its functions in this process; without `barycentrics` it answers the
// triangle ids only, and the host solves the barycentrics.
std::shared_ptr<const plugin::PluginLibrary> raster_stages_plugin(bool barycentrics = true);

}  // namespace raster::properties
