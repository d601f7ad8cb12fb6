// Coverage kernels: which samples of a block row the three edge functions cover, SIMD through Google Highway with
// runtime dispatch. Integer arithmetic only, so every target (and the scalar fallback) finds the same samples.
#pragma once

#include <cstddef>
#include <cstdint>

namespace raster {

// Extra entries the offset rows need past n: a kernel loads whole vectors (up to eight 64-bit lanes).
inline constexpr size_t kCoveragePadding = 8;

// 64-bit words a row of n samples' coverage bits take.
inline constexpr size_t coverage_words(size_t n) { return (n + 63) / 64; }

// Sets bit j (word j / 64, bit j % 64) of `covered` for each j in [0, n) whose three edge values base[i] + offset[i][j]
// are all >= 0 (the fill rule's bias is already in them), clears the others. The offset rows must hold
// n + kCoveragePadding entries, `covered` coverage_words(n). With allow_simd false the scalar fallback runs (the
// same bits).
void coverage_bits(const int64_t (&base)[3], const int64_t* offset0, const int64_t* offset1, const int64_t* offset2,
                   size_t n, uint64_t* covered, bool allow_simd);

}  // namespace raster
