// The peers raster is timed against on the same scenes: the Embree oracle and, when built, Mesa llvmpipe.
#pragma once

#include <string>

#include <benchmark/benchmark.h>

#include "bench/bench_scenes.h"

namespace raster_bench {

// The Embree oracle's frame at the same samples: its scene build and every sample's ray (visibility only, no
// shading, which favours it), robust mode as `raster compare` uses by default.
inline constexpr int kOracleSamples = 16;
std::string oracle_name(const BenchScene& s);
void bm_oracle(benchmark::State& state, const BenchScene* s);

inline constexpr int kLlvmpipeSamples[] = {1, 4};  // llvmpipe's multisampling stops at 4x
std::string llvmpipe_name(const BenchScene& s, int samples);

#ifdef RASTER_HAVE_OSMESA
void bm_llvmpipe(benchmark::State& state, BenchScene* s, int samples);

// Once per scene, untimed: the two images must show the same thing, or the timings compare different work.
// At 1 sample, llvmpipe's non-background pixels against raster's covered samples (within 3%), the pixels the
// two disagree on, and the colour difference; at 4 samples the colour difference of the resolved MSAA images.
bool cross_check(BenchScene& s);
#endif

}  // namespace raster_bench
