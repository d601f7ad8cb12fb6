// A rasterizer plugin (raster_plugin.h): its three functions, found in its shared library or handed over by a
// test, its interface version checked, and one frame in clip space drawn through it into a visibility buffer whose
// ids index the frame's triangles, its barycentrics checked (or solved when the plugin wrote none) and its view
// depths derived.
#pragma once

#include <memory>
#include <string>

#include "backends/plugin/clip_space_frame.h"
#include "backends/plugin/plugin_error.h"
#include "backends/plugin/raster_plugin.h"
#include "raster/rasterize/visibility_buffer.h"

namespace raster::plugin {

// The interface's three entry points.
struct PluginFunctions {
    uint32_t (*abi_version)() = nullptr;
    const char* (*name)() = nullptr;
    int (*draw)(const raster_plugin_frame*, raster_plugin_samples*) = nullptr;
};

class PluginLibrary {
public:
    // Loads the shared library at `path` (a path without a slash is taken in the working folder, never searched
    // for). Throws InputError naming the path when it is missing, is no shared library, lacks one of the three
    // functions or was built against another version of the interface.
    static std::shared_ptr<const PluginLibrary> open(const std::string& path);
    // A plugin whose functions are already in the process (tests); `origin` names it in messages.
    PluginLibrary(const PluginFunctions& functions, std::string origin);
    ~PluginLibrary();
    PluginLibrary(const PluginLibrary&) = delete;
    PluginLibrary& operator=(const PluginLibrary&) = delete;

    const std::string& name() const { return name_; }      // what raster_plugin_name() returned
    const std::string& origin() const { return origin_; }  // the library's path

    // Draws the frame: out.triangle[i] is the index into frame.triangles of the sample's visible triangle or
    // kNoTriangle, out.bary its perspective-correct barycentrics (the plugin's, or solved from the vertices),
    // out.view_depth the view depth they give. Throws PluginRefusal when the plugin refuses the frame, PluginError
    // when it fails or writes what the interface does not allow.
    void draw(const ClipSpaceFrame& frame, VisibilityBuffer& out) const;

private:
    PluginFunctions functions_;
    std::string origin_;
    std::string name_;
    void* handle_ = nullptr;  // dlopen's, when loaded from a file
};

}  // namespace raster::plugin
