// Sample positions: the tables from Vulkan's standard sample locations and the regular grids.
#include "raster/geometry/sample_pattern.h"

#include <algorithm>
#include <cmath>

namespace raster {
namespace {

// Vulkan standard sample locations, origin at the pixel's upper-left corner.
const std::vector<glm::vec2> kStandard1 = {{0.5f, 0.5f}};
const std::vector<glm::vec2> kStandard2 = {{0.75f, 0.75f}, {0.25f, 0.25f}};
const std::vector<glm::vec2> kStandard4 = {{0.375f, 0.125f}, {0.875f, 0.375f}, {0.125f, 0.625f}, {0.625f, 0.875f}};
const std::vector<glm::vec2> kStandard8 = {{0.5625f, 0.3125f}, {0.4375f, 0.6875f}, {0.8125f, 0.5625f},
                                           {0.3125f, 0.1875f}, {0.1875f, 0.8125f}, {0.0625f, 0.4375f},
                                           {0.6875f, 0.9375f}, {0.9375f, 0.0625f}};
const std::vector<glm::vec2> kStandard16 = {
    {0.5625f, 0.5625f}, {0.4375f, 0.3125f}, {0.3125f, 0.625f},  {0.75f, 0.4375f},
    {0.1875f, 0.375f},  {0.625f, 0.8125f},  {0.8125f, 0.6875f}, {0.6875f, 0.1875f},
    {0.375f, 0.875f},   {0.5f, 0.0625f},    {0.25f, 0.125f},    {0.125f, 0.75f},
    {0.0f, 0.5f},       {0.9375f, 0.25f},   {0.875f, 0.9375f},  {0.0625f, 0.0f}};

}  // namespace

std::vector<glm::vec2> sample_offsets(int samples, SamplePattern pattern) {
    if (!sample_count_error(samples, pattern).empty()) return {};
    if (pattern == SamplePattern::standard) {
        switch (samples) {
            case 1: return kStandard1;
            case 2: return kStandard2;
            case 4: return kStandard4;
            case 8: return kStandard8;
            default: return kStandard16;
        }
    }
    const int side = grid_side_of(samples);
    std::vector<glm::vec2> offsets;
    offsets.reserve(static_cast<size_t>(samples));
    for (int j = 0; j < side; ++j)
        for (int i = 0; i < side; ++i)
            offsets.push_back({(static_cast<float>(i) + 0.5f) / static_cast<float>(side),
                               (static_cast<float>(j) + 0.5f) / static_cast<float>(side)});
    return offsets;
}

FixedSampleOffsets fixed_sample_offsets(const std::vector<glm::vec2>& offsets, int fixed_bits) {
    FixedSampleOffsets fixed;
    const double scale = std::ldexp(1.0, fixed_bits);
    const int64_t last = (int64_t{1} << fixed_bits) - 1;  // rounding must not push a sample into the next pixel
    for (const auto& offset : offsets) {
        fixed.x.push_back(std::min<int64_t>(last, std::llround(static_cast<double>(offset.x) * scale)));
        fixed.y.push_back(std::min<int64_t>(last, std::llround(static_cast<double>(offset.y) * scale)));
    }
    return fixed;
}

}  // namespace raster
