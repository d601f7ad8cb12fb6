// Wall-clock milliseconds since a point in time, for the in-process stage timings.
#pragma once

#include <chrono>

namespace raster {

using Clock = std::chrono::steady_clock;

inline double milliseconds_since(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

}  // namespace raster
