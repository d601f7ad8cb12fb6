// The depth test of a block row's covered samples, SIMD through Google Highway with runtime dispatch: each sample's
// key from the triangle's depth plane, compared with the stored key, the winner and key written where it wins.
// Only IEEE-exact operations in per_sample.h's order, so every target gives that scalar path's bits.
#pragma once

#include <cstddef>
#include <cstdint>

#include "raster/rasterize/per_sample.h"

namespace raster {

// Extra entries past a row the kernel may read and write back unchanged (whole vectors of up to eight lanes): the
// depth and winner planes need this many after their last sample.
inline constexpr size_t kDepthPadding = 8;

// One triangle's depth plane over one block row: the key at sample j is plane.at(E1_j, E2_j) (per_sample.h), with
// the exact edge values E_i = base_i + offset_i[j] (the fill-rule bias already taken out of base_i).
struct DepthRow {
    DepthPlane plane;
    int64_t base1, base2;                     // E1 and E2 at the row's first sample corner, without the bias
    const int64_t *offset1, *offset2;         // per sample j, with kCoveragePadding entries past n
    uint32_t triangle;                        // written as the winner: the setup's reference (setup_table.h)
};

struct DepthRowResult {
    bool wrote = false;         // the triangle won some sample
    uint32_t newly_filled = 0;  // samples it won that held nothing before
};

// For each j in [0, n) whose bit is set in `covered` (coverage_kernels.h's layout): the triangle takes sample j
// when winner[j] is kNoTriangle or its key is larger than depth[j] (ties keep the earlier triangle), exactly as
// per_sample.h's depth_test. With allow_simd false the scalar fallback runs (the same result).
DepthRowResult depth_test_row(const DepthRow& row, const uint64_t* covered, size_t n, uint32_t* winner, float* depth,
                              bool allow_simd);

}  // namespace raster
