// Depth-test kernels over Highway: compiled once per SIMD target (foreach_target), dispatched at run time; the
// scalar fallback is called directly when SIMD is not allowed. Built with -ffp-contract=off (CMakeLists.txt).
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "raster/rasterize/depth_kernels.cpp"
#include <hwy/foreach_target.h>  // re-includes this file once per target

#include <hwy/highway.h>

#include <limits>

#include "raster/core/conventions.h"
#include "raster/rasterize/depth_kernels.h"

HWY_BEFORE_NAMESPACE();
namespace raster {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

DepthRowResult DepthTestRow(const DepthRow& row, const uint64_t* covered, size_t n, uint32_t* winner, float* depth) {
    const hn::CappedTag<double, 8> dd;  // at most 8 lanes: kLaneBit, the padding
    const hn::Rebind<int64_t, decltype(dd)> di;
    const hn::Rebind<float, decltype(dd)> df;
    const hn::Rebind<uint32_t, decltype(dd)> du;
    const size_t lanes = hn::Lanes(dd);  // 1 to 8: divides 64, so a vector's bits never straddle two words
    static constexpr uint32_t kLaneBit[8] = {1, 2, 4, 8, 16, 32, 64, 128};
    const auto lane_bit = hn::LoadU(du, kLaneBit);
    const auto base1 = hn::Set(di, row.base1), base2 = hn::Set(di, row.base2);
    const auto d0 = hn::Set(dd, row.plane.d0), k1 = hn::Set(dd, row.plane.d10_over_area),
               k2 = hn::Set(dd, row.plane.d20_over_area);
    const auto half = hn::Set(dd, 0.5);
    const auto float_overflow = hn::Set(dd, 0x1.ffffffp+127);  // FLT_MAX + 2^103: rounds (to even) to inf
    const auto infinity = hn::Set(df, std::numeric_limits<float>::infinity());
    const auto one = hn::Set(dd, 1.0);
    const auto empty_winner = hn::Set(du, kNoTriangle), triangle = hn::Set(du, row.triangle);
    const uint32_t lane_mask = static_cast<uint32_t>((uint64_t{1} << lanes) - 1);
    DepthRowResult result;
    for (size_t j = 0; j < n; j += lanes) {
        const uint32_t bits = static_cast<uint32_t>(covered[j / 64] >> (j % 64)) & lane_mask;
        if (bits == 0) continue;
        const auto e1 = hn::ConvertTo(dd, hn::Add(base1, hn::LoadU(di, row.offset1 + j)));
        const auto e2 = hn::ConvertTo(dd, hn::Add(base2, hn::LoadU(di, row.offset2 + j)));
        auto plane = hn::Add(hn::Add(d0, hn::Mul(e1, k1)), hn::Mul(e2, k2));
        if (row.plane.fixed24) plane = hn::Floor(hn::Add(plane, half));
        // static_cast<float>'s rounding: a double at or beyond FLT_MAX + half its ulp becomes +-inf, where
        // Highway's emulated targets (EMU128, SCALAR) clamp to +-FLT_MAX.
        const auto demoted = hn::DemoteTo(df, plane);
        const auto overflow = hn::DemoteTo(df, hn::IfThenElseZero(hn::Ge(hn::Abs(plane), float_overflow), one));
        const auto key = hn::IfThenElse(hn::Gt(overflow, hn::Zero(df)), hn::CopySign(infinity, demoted), demoted);
        const auto stored_winner = hn::LoadU(du, winner + j);
        const auto stored_key = hn::LoadU(df, depth + j);
        const auto empty = hn::Eq(stored_winner, empty_winner);
        const auto take = hn::And(hn::TestBit(hn::Set(du, bits), lane_bit),
                                  hn::Or(empty, hn::RebindMask(du, hn::Gt(key, stored_key))));
        if (hn::AllFalse(du, take)) continue;
        hn::StoreU(hn::IfThenElse(hn::RebindMask(df, take), key, stored_key), df, depth + j);
        hn::StoreU(hn::IfThenElse(take, triangle, stored_winner), du, winner + j);
        result.wrote = true;
        result.newly_filled += static_cast<uint32_t>(hn::CountTrue(du, hn::And(take, empty)));
    }
    return result;
}

}  // namespace HWY_NAMESPACE
}  // namespace raster
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
#include "raster/rasterize/coverage_kernels.h"

namespace raster {

// A vector of up to 8 lanes starting at the row's last sample reads 7 entries past it.
static_assert(kDepthPadding >= 7 && kCoveragePadding >= 7, "the kernels read whole vectors of up to 8 lanes");

HWY_EXPORT(DepthTestRow);

DepthRowResult depth_test_row(const DepthRow& row, const uint64_t* covered, size_t n, uint32_t* winner, float* depth,
                              bool allow_simd) {
    if (!allow_simd) return HWY_STATIC_DISPATCH(DepthTestRow)(row, covered, n, winner, depth);
    return HWY_DYNAMIC_DISPATCH(DepthTestRow)(row, covered, n, winner, depth);
}

}  // namespace raster
#endif  // HWY_ONCE
