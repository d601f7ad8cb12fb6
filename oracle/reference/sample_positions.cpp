// The documented sample tables (Vulkan's primsrast.adoc, "Standard sample locations"; docs/conventions.md's grid formula).
#include "oracle/reference/sample_positions.h"

#include <algorithm>
#include <cmath>

namespace raster::oracle {

std::vector<glm::dvec2> documented_sample_offsets(int samples, SamplePattern pattern) {
    if (pattern == SamplePattern::grid) {
        // N x N at ((i + 0.5) / N, (j + 0.5) / N), row by row, for N up to 16.
        int side = 1;
        while (side * side < samples) ++side;
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

int sample_grid_bits(int snap_bits) { return std::max(snap_bits, 4); }

std::vector<glm::dvec2> sample_offsets_on_grid(int samples, SamplePattern pattern, int snap_bits) {
    const double steps = std::ldexp(1.0, sample_grid_bits(snap_bits));
    std::vector<glm::dvec2> offsets = documented_sample_offsets(samples, pattern);
    for (glm::dvec2& offset : offsets)
        for (int k = 0; k < 2; ++k) offset[k] = std::min(steps - 1.0, std::round(offset[k] * steps)) / steps;
    return offsets;
}

}  // namespace raster::oracle
