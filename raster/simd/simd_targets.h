// The SIMD targets the kernels (lighting_kernels.h, coverage_kernels.h) dispatch to on this CPU, and a switch that
// pins every kernel to one of them, for tests that check each target gives the same bits.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace raster {

// The Highway targets this build compiles that the CPU runs, best first, the scalar fallback last.
std::vector<int64_t> simd_targets();
std::string simd_target_name(int64_t target);
// Makes every kernel run on `target` from the next call on (0: back to the best the CPU has). Process-wide.
void force_simd_target(int64_t target);

}  // namespace raster
