// Coverage kernels over Highway: compiled once per SIMD target (foreach_target), dispatched at run time; the
// scalar fallback is called directly when SIMD is not allowed.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "raster/rasterize/coverage_kernels.cpp"
#include <hwy/foreach_target.h>  // re-includes this file once per target

#include <hwy/highway.h>

#include "raster/rasterize/coverage_kernels.h"

HWY_BEFORE_NAMESPACE();
namespace raster {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

void CoverageBits(const int64_t* base, const int64_t* offset0, const int64_t* offset1, const int64_t* offset2,
                  size_t n, uint64_t* covered) {
    const hn::ScalableTag<int64_t> d;
    const size_t lanes = hn::Lanes(d);  // 1 to 8: divides 64, so a vector's bits never straddle two words
    const auto zero = hn::Zero(d);
    const auto base0 = hn::Set(d, base[0]), base1 = hn::Set(d, base[1]), base2 = hn::Set(d, base[2]);
    uint64_t outside = 0;  // of the current word: a sample is outside when some edge value is negative, that is
                           // when the sign bit of their OR is set
    for (size_t j = 0; j < n; j += lanes) {
        const auto edges = hn::Or(hn::Or(hn::Add(base0, hn::LoadU(d, offset0 + j)), hn::Add(base1, hn::LoadU(d, offset1 + j))),
                                  hn::Add(base2, hn::LoadU(d, offset2 + j)));
        uint8_t bits[8] = {};
        hn::StoreMaskBits(d, hn::Lt(edges, zero), bits);
        outside |= static_cast<uint64_t>(bits[0]) << (j % 64);
        if ((j + lanes) % 64 == 0 || j + lanes >= n) {
            covered[j / 64] = ~outside;
            outside = 0;
        }
    }
    if (n % 64) covered[(n - 1) / 64] &= (uint64_t{1} << (n % 64)) - 1;  // the padding lanes past n
}

}  // namespace HWY_NAMESPACE
}  // namespace raster
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace raster {

HWY_EXPORT(CoverageBits);

void coverage_bits(const int64_t (&base)[3], const int64_t* offset0, const int64_t* offset1, const int64_t* offset2,
                   size_t n, uint64_t* covered, bool allow_simd) {
    if (!allow_simd) return HWY_STATIC_DISPATCH(CoverageBits)(base, offset0, offset1, offset2, n, covered);
    return HWY_DYNAMIC_DISPATCH(CoverageBits)(base, offset0, offset1, offset2, n, covered);
}

}  // namespace raster
#endif  // HWY_ONCE
