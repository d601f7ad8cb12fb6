// The real implementation and the backends, as values the properties take.
#include "properties/implementation.h"

#include <cstdlib>
#include <string>

#include "backends/plugin/plugin_library.h"
#include "properties/raster_stages_plugin.h"
#ifdef RASTER_WITH_GL
#include "backends/gl/gl_plugin.h"
#endif

namespace raster::properties {

const std::vector<Backend>& drawing_backends() {
    static const std::vector<Backend> list{
        {"reference", RasterPath::reference, false, false, 1, nullptr},
        {"tiled_simd_hiz_2threads", RasterPath::tiled, true, true, 2, nullptr},
        {"tiled_simd_nohiz_1thread", RasterPath::tiled, true, false, 1, nullptr},
        {"tiled_portable_hiz_1thread", RasterPath::tiled, false, true, 1, nullptr},
        {"tiled_portable_nohiz_2threads", RasterPath::tiled, false, false, 2, nullptr},
    };
    return list;
}

const Backend& reference_backend() { return drawing_backends()[0]; }
const Backend& production_backend() { return drawing_backends()[1]; }

std::vector<Backend> plugin_backends() {
    std::vector<Backend> list;
    Backend stages;
    stages.name = "raster_stages_plugin";
    stages.plugin = raster_stages_plugin();
    list.push_back(stages);
    if (const char* path = std::getenv("RASTER_PROPERTIES_PLUGIN"); path && *path) {
        Backend named;
        named.name = "plugin";
#ifdef RASTER_WITH_GL
        if (std::string(path) == "gl") named.plugin = gl::gl_plugin();  // OpenGL on Mesa's EGL (docs/gl.md)
#endif
        if (!named.plugin) named.plugin = plugin::PluginLibrary::open(path);
        list.push_back(named);
    }
    return list;
}

const Implementation& real_implementation() {
    static const Implementation real{"real", StageFunctions{}, BuildingBlocks{}, production_backend()};
    return real;
}

Implementation on_backend(const Implementation& impl, const Backend& backend) {
    Implementation copy = impl;
    copy.backend = backend;
    return copy;
}

}  // namespace raster::properties
