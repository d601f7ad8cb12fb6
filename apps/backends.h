// The renderers the command line runs by name (--backend): raster itself, the GL backend where it was built, and a
// plugin (plugin:PATH, a shared library speaking raster_plugin.h).
#pragma once

#include <memory>
#include <string>

#include <CLI/Validators.hpp>

#include "raster/frame/renderer.h"

namespace raster::cli {

// "raster", "gl" or "plugin:PATH". Throws InputError for gl when this build has no GL backend (RASTER_BUILD_GL=OFF),
// for a plugin that cannot be loaded (naming its path and why), and for any other name.
std::unique_ptr<Renderer> renderer_named(const std::string& name);

// The --backend flag's check: raster, gl or plugin: followed by a path.
CLI::Validator backend_name_validator();

// A short label for file names and report rows: "raster", "gl", or "plugin-STEM" for plugin:PATH (STEM the
// library's file name without its extension and a leading "lib").
std::string backend_label(const std::string& name);

}  // namespace raster::cli
