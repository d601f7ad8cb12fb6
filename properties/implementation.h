// The implementation a property checks: the pipeline's stages and the building blocks outside them, and the
// rasterizer configuration (backend) that drawing properties run them on. The stages and blocks are always the
// real ones; a bug of the catalogue (mutants/bugs.txt) is planted into the source itself, never swapped in here.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "raster/frame/frame.h"
#include "properties/stage_functions.h"
#include "properties/building_blocks.h"

namespace raster::plugin {
class PluginLibrary;  // backends/plugin/plugin_library.h
}

namespace raster::properties {

// Which rasterizer a drawing property runs, and how: the reference full-frame rasterizer, or the tiled production
// renderer (what `raster render` runs) with SIMD coverage (Highway's best target) or its scalar fallback, hierarchical Z on or off, on 1 or 2 threads.
struct Backend {
    std::string name;  // the gtest name suffix, e.g. "tiled_simd_hiz_2threads"
    RasterPath path = RasterPath::tiled;
    bool allow_simd = true;
    bool hierarchical_z = true;
    int threads = 1;
    // Set: a plugin's rasterizer (raster_plugin.h) draws every whole frame in raster's place (stage_driver.h), and
    // only the renderer properties run on it.
    std::shared_ptr<const plugin::PluginLibrary> plugin;
};

// The backends every drawing property runs on: the reference, then four tiled configurations that take every
// pair of values of any two of the axes SIMD x hierarchical Z x threads (a pairwise cover of the eight), the first
// of them the production default.
const std::vector<Backend>& drawing_backends();
const Backend& production_backend();  // tiled, SIMD coverage, hierarchical Z, 2 threads
const Backend& reference_backend();   // the reference rasterizer, 1 thread

// The plugin backends the renderer properties also run on: raster's own stages behind the plugin interface
// (raster_stages_plugin.h), which must pass them, and the library RASTER_PROPERTIES_PLUGIN names, when set (or
// OpenGL for RASTER_PROPERTIES_PLUGIN=gl, where the build has the GL backend), as
// "plugin" (docs/plugins.md). Throws InputError when that library cannot be loaded.
std::vector<Backend> plugin_backends();

struct Implementation {
    std::string name;                // "real"
    StageFunctions stages;           // the production stage functions the properties call
    BuildingBlocks blocks;  // matrix builders and the loader's transform chain
    Backend backend = production_backend();  // what drawing properties rasterize and render with
};

// The real rasterizer: the default stages and blocks, on the production backend.
const Implementation& real_implementation();

// The same implementation on another backend.
Implementation on_backend(const Implementation& impl, const Backend& backend);

}  // namespace raster::properties
