// The memory floor: colour and depth planes memset once per frame, an 8-row strip per task, on kThreads threads.
#include "bench/bandwidth_floor.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <vector>

#include "raster/core/parallel.h"

namespace raster_bench {
namespace {

constexpr int kRowsPerTask = 8;  // 8-row strips: raster's blocks are 8 pixels tall (kBlockSize)

}  // namespace

std::string floor_name(const BenchScene& s) { return "BM_BandwidthFloor/" + s.name + "/samples:1"; }

void bm_bandwidth_floor(benchmark::State& state, const BenchScene* s) {
    const size_t width = static_cast<size_t>(s->scene.settings.width);
    const size_t height = static_cast<size_t>(s->scene.settings.height);
    // Allocated once and kept, as raster keeps its frame buffers between frames.
    std::vector<uint8_t> colour(width * height * 3);
    std::vector<float> depth(width * height);
    const size_t tasks = (height + kRowsPerTask - 1) / kRowsPerTask;
    uint8_t value = 0;
    for (auto _ : state) {
        ++value;  // a different byte every frame: nothing can skip a write as already done
        raster::parallel_for(tasks, kThreads, [&](size_t task) {
            const size_t first = task * kRowsPerTask, rows = std::min<size_t>(kRowsPerTask, height - first);
            std::memset(colour.data() + first * width * 3, value, rows * width * 3);
            std::memset(depth.data() + first * width, value, rows * width * sizeof(float));
        });
        benchmark::DoNotOptimize(colour.data());
        benchmark::DoNotOptimize(depth.data());
        benchmark::ClobberMemory();
    }
}

}  // namespace raster_bench
