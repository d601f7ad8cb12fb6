// Which sample counts each pattern allows.
#include "raster/scene/sample_counts.h"

#include <cmath>

namespace raster {

int grid_side_of(int samples) {
    if (samples < 1) return 0;
    const int side = static_cast<int>(std::lround(std::sqrt(static_cast<double>(samples))));
    return side * side == samples ? side : 0;
}

std::string sample_count_error(int samples, SamplePattern pattern) {
    if (pattern == SamplePattern::standard) {
        if (samples == 1 || samples == 2 || samples == 4 || samples == 8 || samples == 16) return "";
        return "the standard pattern has 1, 2, 4, 8 or 16 samples, not " + std::to_string(samples);
    }
    const int side = grid_side_of(samples);
    if (side >= 1 && side <= kMaxGridSide) return "";
    return "a grid pattern needs a square sample count from 1 to " + std::to_string(kMaxGridSide * kMaxGridSide) +
           " (1, 4, 9, 16, ...), not " + std::to_string(samples);
}

}  // namespace raster
