// Sample positions inside a pixel: the Vulkan standard patterns and N x N grids, in float and in fixed point.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "raster/scene/scene.h"
#include "raster/scene/sample_counts.h"

namespace raster {

// Offsets from the pixel's upper-left corner, each in [0, 1). Standard: 1, 2, 4, 8 or 16 samples (Vulkan
// primsrast.adoc). Grid: samples = N * N, offsets ((i + 0.5) / N, (j + 0.5) / N), row by row.
// Returns an empty vector when the count is not valid for the pattern (see scene/sample_counts.h).
std::vector<glm::vec2> sample_offsets(int samples, SamplePattern pattern);

// The offsets on the fixed-point grid of 1/2^fixed_bits pixel, rounded to nearest. Standard offsets are
// multiples of 1/16 and stay exact for fixed_bits >= 4; grids whose side is not a power of two are rounded.
struct FixedSampleOffsets {
    std::vector<int64_t> x, y;
};
FixedSampleOffsets fixed_sample_offsets(const std::vector<glm::vec2>& offsets, int fixed_bits);

}  // namespace raster
