// The sample positions as ../shared/DESIGN.md, docs/conventions.md and Vulkan's primsrast.adoc document them, independently
// of raster/geometry/sample_pattern.cpp (the oracle's transcription, which shares nothing with raster either), in
// pixels and on the fixed-point grid.
#pragma once

#include <vector>

#include <glm/vec2.hpp>

#include "raster/scene/scene.h"
#include "properties/reference/coverage_reference.h"

namespace raster::properties {

// Offsets from the pixel's upper-left corner: the standard tables for 1, 2, 4, 8 and 16 samples, or the N x N
// grid ((i + 0.5) / N, (j + 0.5) / N) row by row. Empty when the count is not documented for the pattern.
std::vector<glm::dvec2> documented_sample_offsets(int samples, SamplePattern pattern);

// The same on the grid of 1/2^fixed_bits pixel, as conventions.h and sample_pattern.h document the rounding:
// to nearest (halves away from zero), and never past 2^fixed_bits - 1 (a sample stays inside its pixel).
std::vector<reference::Point> documented_fixed_offsets(int samples, SamplePattern pattern, int fixed_bits);

}  // namespace raster::properties
