// The documented sample tables, copied from ../shared/DESIGN.md ("Standard sample positions") and Vulkan for 2 samples.
#include "properties/reference/documented_samples.h"

#include <algorithm>
#include <cmath>

namespace raster::properties {

std::vector<glm::dvec2> documented_sample_offsets(int samples, SamplePattern pattern) {
    if (pattern == SamplePattern::grid) {
        const int side = static_cast<int>(std::lround(std::sqrt(static_cast<double>(samples))));
        if (samples < 1 || side * side != samples || side > 16) return {};
        std::vector<glm::dvec2> grid;
        for (int j = 0; j < side; ++j)
            for (int i = 0; i < side; ++i) grid.push_back({(i + 0.5) / side, (j + 0.5) / side});
        return grid;
    }
    switch (samples) {
        case 1: return {{0.5, 0.5}};
        case 2: return {{0.75, 0.75}, {0.25, 0.25}};
        case 4: return {{0.375, 0.125}, {0.875, 0.375}, {0.125, 0.625}, {0.625, 0.875}};
        case 8:
            return {{0.5625, 0.3125}, {0.4375, 0.6875}, {0.8125, 0.5625}, {0.3125, 0.1875},
                    {0.1875, 0.8125}, {0.0625, 0.4375}, {0.6875, 0.9375}, {0.9375, 0.0625}};
        case 16:
            return {{0.5625, 0.5625}, {0.4375, 0.3125}, {0.3125, 0.625}, {0.75, 0.4375},
                    {0.1875, 0.375},  {0.625, 0.8125},  {0.8125, 0.6875}, {0.6875, 0.1875},
                    {0.375, 0.875},   {0.5, 0.0625},    {0.25, 0.125},    {0.125, 0.75},
                    {0.0, 0.5},       {0.9375, 0.25},   {0.875, 0.9375},  {0.0625, 0.0}};
        default: return {};
    }
}

std::vector<reference::Point> documented_fixed_offsets(int samples, SamplePattern pattern, int fixed_bits) {
    const double scale = std::ldexp(1.0, fixed_bits);
    const int64_t last = (int64_t{1} << fixed_bits) - 1;
    std::vector<reference::Point> fixed;
    for (const glm::dvec2& offset : documented_sample_offsets(samples, pattern))
        fixed.push_back({std::min<int64_t>(last, std::llround(offset.x * scale)),
                         std::min<int64_t>(last, std::llround(offset.y * scale))});
    return fixed;
}

}  // namespace raster::properties
