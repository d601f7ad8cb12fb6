// A rasterizer plugin (raster_plugin.h): its three functions, found in its shared library or handed over by a
// test, its interface version checked, and one frame in clip space drawn through it into a visibility buffer whose
// ids index the frame's triangles, its barycentrics checked (or solved when the plugin wrote none) and its view
// depths derived.
#pragma once

#include <array>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "backends/plugin/raster_plugin.h"
#include "raster/rasterize/visibility_buffer.h"

namespace raster::plugin {

// The plugin failed, or broke the interface's contract (an id past the frame's triangles, non-finite
// barycentrics): a finding about the plugin, not bad input.
class PluginError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// What the plugin is asked to draw: raster_plugin_frame, in C++ types.
struct ClipSpaceFrame {
    int width = 0, height = 0;
    std::vector<glm::vec2> sample_offsets;  // from the pixel's upper-left corner
    int subpixel_bits = 8;
    bool cull_backfaces = false;
    bool orthographic = false;
    float near_plane = 0.1f, far_plane = 100.0f;
    std::vector<std::array<glm::vec4, 3>> triangles;  // clip space, a b c
};

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
    // out.view_depth the view depth they give. Throws InputError when the plugin refuses the frame, PluginError when
    // it fails or writes what the interface does not allow.
    void draw(const ClipSpaceFrame& frame, VisibilityBuffer& out) const;

private:
    PluginFunctions functions_;
    std::string origin_;
    std::string name_;
    void* handle_ = nullptr;  // dlopen's, when loaded from a file
};

}  // namespace raster::plugin
