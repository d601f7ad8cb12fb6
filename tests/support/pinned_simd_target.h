// Pins every SIMD kernel to one Highway target for the life of a test object, and back to the best on exit.
#pragma once

#include <cstdint>

#include "raster/simd/simd_targets.h"

namespace raster::test_support {

class PinnedSimdTarget {
public:
    explicit PinnedSimdTarget(int64_t target) { force_simd_target(target); }
    ~PinnedSimdTarget() { force_simd_target(0); }
    PinnedSimdTarget(const PinnedSimdTarget&) = delete;
    PinnedSimdTarget& operator=(const PinnedSimdTarget&) = delete;
};

}  // namespace raster::test_support
