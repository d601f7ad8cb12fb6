// Sample positions inside a pixel: the Vulkan standard patterns and N x N grids, in float and in fixed point.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "raster/scene.h"

namespace raster {

inline constexpr int kMaxGridSide = 16;  // grids up to 16 x 16 = 256 samples per pixel

// Offsets from the pixel's upper-left corner, each in [0, 1). Standard: 1, 2, 4, 8 or 16 samples (Vulkan
// primsrast.adoc). Grid: samples = N * N, offsets ((i + 0.5) / N, (j + 0.5) / N), row by row.
// Returns an empty vector when the count is not valid for the pattern (see sample_count_error).
std::vector<glm::vec2> sample_offsets(int samples, SamplePattern pattern);

// Empty when `samples` is valid for `pattern`, otherwise a message saying what is allowed.
std::string sample_count_error(int samples, SamplePattern pattern);

// The offsets on the fixed-point grid of 1/2^fixed_bits pixel, rounded to nearest. Standard offsets are
// multiples of 1/16 and stay exact for fixed_bits >= 4; grids whose side is not a power of two are rounded.
struct FixedSampleOffsets {
    std::vector<int64_t> x, y;
};
FixedSampleOffsets fixed_sample_offsets(const std::vector<glm::vec2>& offsets, int fixed_bits);

}  // namespace raster
