// The errors a plugin raises: its failure, what the framework found in the rasterizer under test; and its refusal
// of a frame it does not draw, the plugin's limit.
#pragma once

#include <stdexcept>
#include <string>

#include "raster/core/errors.h"

namespace raster::plugin {

// The plugin failed, or broke the interface's contract (an id past the frame's triangles, non-finite
// barycentrics): a finding about the plugin, not bad input.
class PluginError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// The plugin refused the frame (RASTER_PLUGIN_REFUSED): an input error for the command line (exit 2), a case to
// discard for the properties, an input to skip for the fuzzer.
class PluginRefusal : public InputError {
public:
    explicit PluginRefusal(const std::string& message) : InputError(message) {}
};

}  // namespace raster::plugin
