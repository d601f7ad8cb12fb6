// The error a plugin's failure raises: what the framework found in the rasterizer under test, not bad input.
#pragma once

#include <stdexcept>

namespace raster::plugin {

// The plugin failed, or broke the interface's contract (an id past the frame's triangles, non-finite
// barycentrics): a finding about the plugin, not bad input.
class PluginError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

}  // namespace raster::plugin
