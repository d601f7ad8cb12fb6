// Highway's run-time target choice for this program, decided from GCC's CPU model (__builtin_cpu_supports) instead
// of libhwy.so: that library calibrates a timer when it is loaded, which cost every `raster` process ~5-10 ms
// (measured: an empty program linked with -lhwy takes 11 ms to run instead of 1). The dispatch tables, the
// targets' code and ChosenTarget are Highway's own, from its headers.
#include "raster/pipeline/simd_targets.h"

#include <hwy/targets.h>

namespace hwy {
namespace {

bool cpu_has_all(std::initializer_list<bool> features) {
    for (bool feature : features)
        if (!feature) return false;
    return true;
}

}  // namespace

// The x86 targets this build compiles, each with the CPU features Highway's own detection requires for it (GCC's
// checks include the operating system's support for the AVX and AVX-512 register state); the scalar fallbacks
// always.
int64_t SupportedTargets() {
    static const int64_t targets = [] {
        int64_t found = HWY_EMU128 | HWY_SCALAR;
        __builtin_cpu_init();
        const bool ssse3 = cpu_has_all({__builtin_cpu_supports("sse2") != 0, __builtin_cpu_supports("ssse3") != 0});
        const bool sse4 = ssse3 && cpu_has_all({__builtin_cpu_supports("sse4.1") != 0,
                                                __builtin_cpu_supports("sse4.2") != 0,
                                                __builtin_cpu_supports("pclmul") != 0,
                                                __builtin_cpu_supports("aes") != 0});
        const bool avx2 = sse4 && cpu_has_all({__builtin_cpu_supports("avx") != 0, __builtin_cpu_supports("avx2") != 0,
                                               __builtin_cpu_supports("bmi") != 0, __builtin_cpu_supports("bmi2") != 0,
                                               __builtin_cpu_supports("fma") != 0, __builtin_cpu_supports("f16c") != 0,
                                               __builtin_cpu_supports("lzcnt") != 0});
        const bool avx3 = avx2 && cpu_has_all({__builtin_cpu_supports("avx512f") != 0,
                                               __builtin_cpu_supports("avx512vl") != 0,
                                               __builtin_cpu_supports("avx512dq") != 0,
                                               __builtin_cpu_supports("avx512bw") != 0});
        if (ssse3) found |= HWY_SSSE3;
        if (sse4) found |= HWY_SSE4;
        if (avx2) found |= HWY_AVX2;
        if (avx3) found |= HWY_AVX3;
        return found;
    }();
    return targets;
}

ChosenTarget& GetChosenTarget() {
    static ChosenTarget chosen;
    return chosen;
}

}  // namespace hwy

namespace raster {

std::vector<int64_t> simd_targets() { return hwy::SupportedAndGeneratedTargets(); }

std::string simd_target_name(int64_t target) { return hwy::TargetName(target); }

void force_simd_target(int64_t target) {
    hwy::GetChosenTarget().Update(target == 0 ? hwy::SupportedTargets() : target);
}

}  // namespace raster
