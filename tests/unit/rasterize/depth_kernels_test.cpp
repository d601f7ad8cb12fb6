// The depth kernel: a block row's depth test, the same on every Highway target the CPU runs and on the scalar
// fallback, and equal to per_sample.h's DepthPlane and depth_test (the reference rasterizer's) applied one covered
// sample at a time: keys, winners, ties, empty samples, NaN stored keys, fixed24 levels, keys beyond float's range,
// the padding untouched; and a fixed24 key is the nearest 24-bit level.
#include "raster/rasterize/depth_kernels.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <iterator>
#include <limits>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "raster/rasterize/coverage_kernels.h"
#include "raster/rasterize/per_sample.h"
#include "raster/simd/simd_targets.h"
#include "tests/support/pinned_simd_target.h"

namespace raster {
namespace {

struct Case {
    TriangleSetup setup;  // only its depth plane: depth[3], area2, depth_fixed24
    int64_t base1, base2;
    std::vector<int64_t> offset1, offset2;
    std::vector<uint64_t> covered;
    std::vector<uint32_t> winner;
    std::vector<float> depth;
};

// Edge values near 0 and up to +-2^56 (conventions.h's range), planes with the depth formats' key ranges, stored
// samples empty, nearer, farther, tied with the triangle's own key, or NaN.
Case random_case(std::mt19937_64& rng, size_t n, bool fixed24) {
    std::uniform_int_distribution<int64_t> small(0, 4096), large(-(int64_t{1} << 52), int64_t{1} << 52);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::uniform_int_distribution<int> pick(0, 5);
    Case c;
    c.setup.area2 = int64_t{1} + static_cast<int64_t>(unit(rng) * 1e12);
    c.setup.depth_fixed24 = fixed24;
    for (double& key : c.setup.depth) key = fixed24 ? -unit(rng) * kFixed24Levels : unit(rng);
    // Sometimes a flat plane beyond float's range (only out-of-range input reaches it): static_cast<float>
    // rounds from FLT_MAX + 2^103 up to inf, just below it down to FLT_MAX.
    const double beyond[] = {1e39, -1e39, 0x1.ffffffp+127, -0x1.ffffffp+127, 0x1.fffffefffffffp+127, 3.4028234e38};
    if (pick(rng) == 0) {
        const double flat = beyond[std::uniform_int_distribution<size_t>(0, std::size(beyond) - 1)(rng)];
        for (double& key : c.setup.depth) key = flat;
    }
    c.base1 = pick(rng) == 0 ? large(rng) * 16 : small(rng);
    c.base2 = pick(rng) == 0 ? large(rng) * 16 : small(rng);
    for (auto* offset : {&c.offset1, &c.offset2}) {
        offset->resize(n + kCoveragePadding, std::numeric_limits<int64_t>::min() / 4);
        for (size_t j = 0; j < n; ++j) (*offset)[j] = pick(rng) == 0 ? large(rng) : small(rng) * 97;
    }
    c.covered.assign(coverage_words(n), 0);
    for (size_t j = 0; j < n; ++j)
        if (pick(rng) != 0) c.covered[j / 64] |= uint64_t{1} << (j % 64);
    const DepthPlane plane(c.setup);
    c.winner.assign(n + kDepthPadding, 77u);
    c.depth.assign(n + kDepthPadding, 0.25f);
    for (size_t j = 0; j < n; ++j) {
        const float own = plane.at(c.base1 + c.offset1[j], c.base2 + c.offset2[j]);
        switch (pick(rng)) {
            case 0: c.winner[j] = kNoTriangle; break;
            case 1: c.depth[j] = own; break;  // a tie: the earlier triangle stays
            case 2: c.depth[j] = std::nextafter(own, -std::numeric_limits<float>::infinity()); break;
            case 3: c.depth[j] = std::nextafter(own, std::numeric_limits<float>::infinity()); break;
            case 4: c.depth[j] = std::numeric_limits<float>::quiet_NaN(); break;
            default: c.depth[j] = static_cast<float>(fixed24 ? -unit(rng) * kFixed24Levels : unit(rng)); break;
        }
    }
    return c;
}

struct Outcome {
    std::vector<uint32_t> winner;
    std::vector<uint32_t> depth_bits;  // compared bit for bit (NaN included)
    bool wrote;
    uint32_t newly_filled;
};

Outcome bits_of(const std::vector<uint32_t>& winner, const std::vector<float>& depth, bool wrote, uint32_t filled) {
    Outcome out{winner, std::vector<uint32_t>(depth.size()), wrote, filled};
    std::memcpy(out.depth_bits.data(), depth.data(), depth.size() * sizeof(float));
    return out;
}

bool operator==(const Outcome& a, const Outcome& b) {
    return a.winner == b.winner && a.depth_bits == b.depth_bits && a.wrote == b.wrote &&
           a.newly_filled == b.newly_filled;
}

constexpr uint32_t kTriangle = 5;

// The definition: per_sample.h's key and test, one covered sample at a time.
Outcome reference(Case c, size_t n) {
    const DepthPlane plane(c.setup);
    bool wrote = false;
    uint32_t filled = 0;
    for (size_t j = 0; j < n; ++j) {
        if (!((c.covered[j / 64] >> (j % 64)) & 1)) continue;
        const DepthTestResult test = depth_test(c.winner.data(), c.depth.data(), j,
                                                plane.at(c.base1 + c.offset1[j], c.base2 + c.offset2[j]), kTriangle);
        wrote = wrote || test.written;
        filled += test.was_empty;
    }
    return bits_of(c.winner, c.depth, wrote, filled);
}

Outcome kernel(Case c, size_t n, bool allow_simd) {
    const DepthPlane plane(c.setup);
    const DepthRow row{plane, c.base1, c.base2, c.offset1.data(), c.offset2.data(), kTriangle};
    const DepthRowResult result = depth_test_row(row, c.covered.data(), n, c.winner.data(), c.depth.data(), allow_simd);
    return bits_of(c.winner, c.depth, result.wrote, result.newly_filled);
}

TEST(DepthKernels, everyTargetGivesPerSampleDepthTestsResultSampleBySample) {
    std::mt19937_64 rng(20261203);
    const std::vector<int64_t> targets = simd_targets();
    for (const bool fixed24 : {false, true})
        for (size_t n : {1u, 3u, 4u, 7u, 8u, 12u, 32u, 63u, 64u, 65u, 128u, 200u, 512u})
            for (int trial = 0; trial < 20; ++trial) {
                const Case c = random_case(rng, n, fixed24);
                const Outcome expected = reference(c, n);
                EXPECT_TRUE(kernel(c, n, false) == expected) << "scalar fallback, n = " << n << ", fixed24 " << fixed24;
                for (const int64_t target : targets) {
                    const test_support::PinnedSimdTarget pinned(target);
                    EXPECT_TRUE(kernel(c, n, true) == expected)
                        << simd_target_name(target) << ", n = " << n << ", fixed24 " << fixed24;
                }
            }
}

// A fixed24 key is the 24-bit level nearest the plane's value (a D24 buffer rounds, halves up), not the level below
// it: on a flat plane, values a fraction of a level apart, with their levels written out.
TEST(DepthPlane, aFixed24KeyIsTheNearestLevel) {
    const struct {
        double value;
        float level;
    } kCases[] = {{-1000.3, -1000.0f}, {-1000.5, -1000.0f},         {-1000.7, -1001.0f},
                  {-0.2, 0.0f},        {-16777214.6, -16777215.0f}, {-16777215.0, -16777215.0f}};
    for (const auto& c : kCases) {
        TriangleSetup setup;
        setup.area2 = 1024;
        setup.depth_fixed24 = true;
        for (double& key : setup.depth) key = c.value;
        EXPECT_EQ(DepthPlane(setup).at(0, 0), c.level) << c.value;
        EXPECT_EQ(DepthPlane(setup).at(512, -300), c.level) << c.value;
        setup.depth_fixed24 = false;
        EXPECT_EQ(DepthPlane(setup).at(0, 0), static_cast<float>(c.value)) << c.value;  // other formats: the value
    }
}

}  // namespace
}  // namespace raster
