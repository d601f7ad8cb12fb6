// What a plugin is asked to draw: raster_plugin_frame, in C++ types.
#pragma once

#include <array>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

namespace raster::plugin {

// One frame for a plugin: raster_plugin_frame, in C++ types.
struct ClipSpaceFrame {
    int width = 0, height = 0;
    std::vector<glm::vec2> sample_offsets;  // from the pixel's upper-left corner
    int subpixel_bits = 8;
    bool cull_backfaces = false;
    bool orthographic = false;
    float near_plane = 0.1f, far_plane = 100.0f;
    std::vector<std::array<glm::vec4, 3>> triangles;  // clip space, a b c
};

}  // namespace raster::plugin
