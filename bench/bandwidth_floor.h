// The memory floor of a frame: writing its colour image and its depth plane once, with memset, on raster's
// threads, in raster's tile rows. No renderer can write a frame faster; raster's frame time over it says how much
// of the frame is work beyond that.
#pragma once

#include <string>

#include <benchmark/benchmark.h>

#include "bench/bench_scenes.h"

namespace raster_bench {

std::string floor_name(const BenchScene& s);

// One frame's floor for the scene at 1 sample: 3 bytes of colour and 4 of depth per pixel, written once.
void bm_bandwidth_floor(benchmark::State& state, const BenchScene* s);

}  // namespace raster_bench
