// The renderers the command line runs by name (backends.h).
#include "apps/backends.h"

#include <filesystem>

#include "backends/plugin/plugin_renderer.h"
#include "raster/core/errors.h"
#ifdef RASTER_WITH_GL
#include "backends/gl/gl_renderer.h"
#endif

namespace raster::cli {
namespace {

constexpr const char* kPluginPrefix = "plugin:";

bool is_plugin(const std::string& name) { return name.rfind(kPluginPrefix, 0) == 0; }

}  // namespace

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
    if (is_plugin(name))
        return std::make_unique<plugin::PluginRenderer>(
            plugin::PluginLibrary::open(name.substr(std::string(kPluginPrefix).size())));
    throw InputError("no backend named '" + name + "' (raster, gl or plugin:PATH)");
}

CLI::Validator backend_name_validator() {
    return CLI::Validator(
        [](std::string& name) -> std::string {
            if (name == "raster" || name == "gl") return "";
            if (is_plugin(name) && name.size() > std::string(kPluginPrefix).size()) return "";
            return "'" + name + "' is not a backend: raster, gl or plugin:PATH (a shared library; docs/plugins.md)";
        },
        "raster|gl|plugin:PATH");
}

std::string backend_label(const std::string& name) {
    if (!is_plugin(name)) return name;
    std::string stem = std::filesystem::path(name.substr(std::string(kPluginPrefix).size())).stem().string();
    if (stem.rfind("lib", 0) == 0 && stem.size() > 3) stem = stem.substr(3);
    return "plugin-" + stem;
}

}  // namespace raster::cli
