// Where the samples of a pixel are, as the documented conventions (docs/conventions.md) document them: the Vulkan standard tables for
// 1, 2, 4, 8 and 16 samples and the N x N grids, placed on the fixed-point grid of 1/2^max(snap_bits, 4) pixel.
// Transcribed here from the documents, not from raster's sample code.
#pragma once

#include <vector>

#include <glm/vec2.hpp>

#include "raster/scene/scene.h"

namespace raster::oracle {

// Offsets from the pixel's upper-left corner, in pattern order, as the documents print them; empty for a count
// the pattern does not have.
std::vector<glm::dvec2> documented_sample_offsets(int samples, SamplePattern pattern);

// The bits of the fixed-point grid sample positions live on: max(snap_bits, 4).
int sample_grid_bits(int snap_bits);

// The same offsets on that grid, in pixels: each rounded to the nearest grid point (halves away from zero) and
// kept inside the pixel (at most the last grid point before 1).
std::vector<glm::dvec2> sample_offsets_on_grid(int samples, SamplePattern pattern, int snap_bits);

}  // namespace raster::oracle
