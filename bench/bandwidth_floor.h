// The memory floor of a frame: writing its colour image and one depth value per pixel once, with memset, on raster's
// threads, in 8-row strips. A reference for the frame's time rather than a strict bound (raster's tiled frame keeps
// depth in per-tile scratch); raster's frame time over it says how much of the frame is work beyond writing it.
#pragma once

#include <string>

#include <benchmark/benchmark.h>

#include "bench/bench_scenes.h"

namespace raster_bench {

std::string floor_name(const BenchScene& s);

// One frame's floor for the scene at 1 sample: 3 bytes of colour and 4 of depth per pixel, written once.
void bm_bandwidth_floor(benchmark::State& state, const BenchScene* s);

}  // namespace raster_bench
