// raster's own benchmark: one frame of a bench scene at each sample count, SSAA and MSAA.
#pragma once

#include <string>

#include <benchmark/benchmark.h>

#include "bench/bench_scenes.h"
#include "raster/frame/render.h"

namespace raster_bench {

// raster's cases: SSAA (every sample shaded) and MSAA (shaded once per pixel per triangle) at 1, 4 and 16 samples;
// 4-sample MSAA is the like-for-like partner of llvmpipe's 4x MSAA.
struct RasterCase {
    int samples;
    bool msaa;
};
inline constexpr RasterCase kRasterCases[] = {{1, false}, {4, false}, {4, true}, {16, false}, {16, true}};

// Timed frames take the fast path (no full-frame visibility buffer); the cross-check keeps it to count coverage.
raster::RenderOptions render_options(bool keep_visibility);

std::string raster_name(const BenchScene& s, const RasterCase& c);

void bm_raster(benchmark::State& state, const BenchScene* s, RasterCase c);

}  // namespace raster_bench
