// Highway's run-time target choice for this program, decided from the CPU's CPUID bits instead
// of libhwy.so: that library calibrates a timer when it is loaded, which cost every `raster` process ~5-10 ms
// (measured: an empty program linked with -lhwy takes 11 ms to run instead of 1). The dispatch tables, the
// targets' code and ChosenTarget are Highway's own, from its headers.
#include "raster/simd/simd_targets.h"

#include <cpuid.h>

#include <cstdint>

#include <hwy/targets.h>

namespace hwy {
namespace {

// The CPU's feature bits, read with CPUID and XGETBV directly: GCC's __builtin_cpu_supports and clang's accept
// different feature names (clang 14 knows neither "f16c" nor "lzcnt"), and the fuzz targets build with clang.
struct CpuFeatures {
    uint32_t leaf1_ecx = 0, leaf1_edx = 0, leaf7_ebx = 0, extended_ecx = 0;
    uint64_t os_saved_state = 0;  // XCR0: which register states the operating system saves

    static bool bit(uint32_t word, int index) { return ((word >> index) & 1u) != 0; }
};

CpuFeatures read_cpu_features() {
    CpuFeatures cpu;
    unsigned eax = 0, ebx = 0, ecx = 0, edx = 0;
    if (__get_cpuid(1, &eax, &ebx, &ecx, &edx)) {
        cpu.leaf1_ecx = ecx;
        cpu.leaf1_edx = edx;
    }
    if (__get_cpuid_count(7, 0, &eax, &ebx, &ecx, &edx)) cpu.leaf7_ebx = ebx;
    if (__get_cpuid(0x80000001u, &eax, &ebx, &ecx, &edx)) cpu.extended_ecx = ecx;
    if (CpuFeatures::bit(cpu.leaf1_ecx, 27)) {  // OSXSAVE: XGETBV may be executed
        uint32_t low = 0, high = 0;
        __asm__ volatile("xgetbv" : "=a"(low), "=d"(high) : "c"(0));
        cpu.os_saved_state = (uint64_t{high} << 32) | low;
    }
    return cpu;
}

}  // namespace

// The x86 targets this build compiles, each with the CPU features Highway's own detection requires for it, and the
// operating system's support for the AVX and AVX-512 register state; the scalar fallbacks always.
int64_t SupportedTargets() {
    static const int64_t targets = [] {
        const CpuFeatures cpu = read_cpu_features();
        auto ecx1 = [&](int index) { return CpuFeatures::bit(cpu.leaf1_ecx, index); };
        auto ebx7 = [&](int index) { return CpuFeatures::bit(cpu.leaf7_ebx, index); };
        const bool ssse3 = CpuFeatures::bit(cpu.leaf1_edx, 26) && ecx1(0) && ecx1(9);  // SSE2, SSE3, SSSE3
        const bool sse4 = ssse3 && ecx1(19) && ecx1(20) && ecx1(1) && ecx1(25);        // SSE4.1, 4.2, CLMUL, AES
        const bool os_saves_avx = (cpu.os_saved_state & 0x6) == 0x6;                     // XMM and YMM state
        const bool avx2 = sse4 && os_saves_avx && ecx1(28) && ebx7(5) && ebx7(3) && ebx7(8)  // AVX AVX2 BMI BMI2
                          && ecx1(12) && ecx1(29) && CpuFeatures::bit(cpu.extended_ecx, 5);  // FMA F16C LZCNT
        const bool os_saves_avx512 = (cpu.os_saved_state & 0xE0) == 0xE0;                // opmask, ZMM state
        const bool avx3 = avx2 && os_saves_avx512 && ebx7(16) && ebx7(31) && ebx7(17) && ebx7(30);  // F VL DQ BW
        int64_t found = HWY_EMU128 | HWY_SCALAR;
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
