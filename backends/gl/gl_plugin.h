// OpenGL behind the plugin interface (raster_plugin.h): clip-space triangles drawn by llvmpipe through the GL
// backend's visibility pass, so that the renderer properties (the fill rule, watertightness, coverage against the
// exact reference, depth) judge the GL implementation as they judge any plugin (docs/gl.md). In process: its
// functions are this library's, its context one for the process.
#pragma once

#include <memory>

#include "backends/plugin/plugin_library.h"

namespace raster::gl {

// The plugin, named after the implementation ("gl (llvmpipe ...)"). It refuses, by name, frames whose sample count
// or positions the implementation does not have and sub-pixel precision other than its GL_SUBPIXEL_BITS. Throws
// std::runtime_error when no context can be made.
std::shared_ptr<const plugin::PluginLibrary> gl_plugin();

}  // namespace raster::gl
