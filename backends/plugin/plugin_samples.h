// A plugin's per-sample answer checked against the interface's contract and completed: every id a triangle of the
// frame or none, the plugin's barycentrics finite (or, when it wrote none, solved from the clip-space vertices at
// each covered sample), and the view depth they give.
#pragma once

#include <array>
#include <string>

#include <glm/vec3.hpp>

#include "backends/plugin/clip_space_frame.h"
#include "backends/plugin/plugin_error.h"
#include "raster/rasterize/visibility_buffer.h"

namespace raster::plugin {

// The perspective-correct barycentrics of `triangle` at the screen point `screen` (pixels, y down) of a
// width x height frame: the weights whose combination of the clip-space vertices projects there, summing to 1.
// (1/3, 1/3, 1/3) where the point sees the triangle's plane edge-on (no solution).
glm::dvec3 solve_barycentrics(const std::array<glm::vec4, 3>& triangle, glm::dvec2 screen, int width, int height);

// A clip-space vertex's view depth: w under a perspective camera, far - (z / w)(far - near) under an
// orthographic one (raster_plugin.h).
double vertex_view_depth(const glm::vec4& clip, const ClipSpaceFrame& frame);

// Checks the plugin's answer in `samples` (ids as the plugin wrote them, barycentrics when `barycentrics_written`)
// and completes it: barycentrics solved where the plugin wrote none, zero for empty samples, and the view depths.
// Throws PluginError naming `plugin`, the sample and what is wrong.
void complete_samples(const ClipSpaceFrame& frame, bool barycentrics_written, const std::string& plugin,
                      VisibilityBuffer& samples);

}  // namespace raster::plugin
