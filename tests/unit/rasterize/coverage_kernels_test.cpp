// The coverage kernel: the covered samples of a block row, the same on every Highway target the CPU runs and on
// the scalar fallback, and equal to the definition (every edge value >= 0) written as a plain loop.
#include "raster/rasterize/coverage_kernels.h"

#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "raster/simd/simd_targets.h"
#include "tests/support/pinned_simd_target.h"

namespace raster {
namespace {

struct Row {
    int64_t base[3];
    std::vector<int64_t> offset[3];
};

// Edge values around 0 (where the fill rule decides), and large ones of both signs (the 64-bit range the edge
// functions use, conventions.h): offsets in +-2^52, bases in +-2^56, so no sum overflows.
Row random_row(std::mt19937_64& rng, size_t n) {
    std::uniform_int_distribution<int64_t> small(-3, 3), large(-(int64_t{1} << 52), int64_t{1} << 52);
    std::uniform_int_distribution<int> pick(0, 3);
    Row row;
    for (int i = 0; i < 3; ++i) {
        row.base[i] = pick(rng) == 0 ? small(rng) : large(rng) * 16;
        row.offset[i].resize(n + kCoveragePadding, std::numeric_limits<int64_t>::min() / 4);  // padding: "outside"
        for (size_t j = 0; j < n; ++j) row.offset[i][j] = pick(rng) == 0 ? small(rng) - row.base[i] : large(rng);
    }
    return row;
}

std::vector<uint64_t> bits_of(const Row& row, size_t n, bool allow_simd) {
    std::vector<uint64_t> bits(coverage_words(n), 0x5555555555555555u);  // every word must be written
    coverage_bits(row.base, row.offset[0].data(), row.offset[1].data(), row.offset[2].data(), n, bits.data(),
                  allow_simd);
    return bits;
}

TEST(CoverageKernels, everyTargetFindsTheSamplesWhoseThreeEdgeValuesAreAllNonNegative) {
    std::mt19937_64 rng(20261203);
    const std::vector<int64_t> targets = simd_targets();
    for (size_t n : {1u, 3u, 4u, 7u, 8u, 12u, 32u, 63u, 64u, 65u, 128u, 200u, 512u}) {
        for (int trial = 0; trial < 20; ++trial) {
            const Row row = random_row(rng, n);
            std::vector<uint64_t> expected(coverage_words(n), 0);
            for (size_t j = 0; j < n; ++j)
                if (row.base[0] + row.offset[0][j] >= 0 && row.base[1] + row.offset[1][j] >= 0 &&
                    row.base[2] + row.offset[2][j] >= 0)
                    expected[j / 64] |= uint64_t{1} << (j % 64);
            EXPECT_EQ(bits_of(row, n, false), expected) << "scalar fallback, n = " << n;
            for (const int64_t target : targets) {
                const test_support::PinnedSimdTarget pinned(target);
                EXPECT_EQ(bits_of(row, n, true), expected) << simd_target_name(target) << ", n = " << n;
            }
        }
    }
}

}  // namespace
}  // namespace raster
