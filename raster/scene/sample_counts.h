// Which sample counts each pattern allows: the standard pattern's 1, 2, 4, 8 and 16, and square grids up to 16 x 16.
#pragma once

#include <string>

#include "raster/scene/scene.h"

namespace raster {

inline constexpr int kMaxGridSide = 16;  // grids up to 16 x 16 = 256 samples per pixel

// Empty when `samples` is valid for `pattern`, otherwise a message saying what is allowed.
std::string sample_count_error(int samples, SamplePattern pattern);

// N when samples = N * N for a whole N >= 1, else 0.
int grid_side_of(int samples);

}  // namespace raster
