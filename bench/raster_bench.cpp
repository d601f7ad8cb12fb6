// raster_bench: raster's frame time on the bench scenes (teapot, organic scan, icosphere, heavy occlusion) and, in
// the same run, Mesa llvmpipe (OSMesa) drawing the same triangles with the same camera and per-fragment
// Blinn-Phong; ends with a median-time comparison table per scene.
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <iterator>
#include <memory>
#include <string>
#include <vector>

#include "bench/bandwidth_floor.h"
#include "bench/bench_scenes.h"
#include "bench/benchmark_flags.h"
#include "bench/peer_benchmarks.h"
#include "bench/raster_benchmark.h"
#include "bench/summary_table.h"

using namespace raster_bench;

int main(int argc, char** argv) {
    // Interleaving the repetitions of raster and llvmpipe in random order spreads slow drifts in machine load over
    // both instead of charging one.
    std::vector<char*> flags(argv + 1, argv + argc);
    const std::vector<std::string> wanted = take_scenes_flag(flags);
    if (!initialize_benchmark(argv[0],
                              {"--benchmark_repetitions=7", "--benchmark_report_aggregates_only=true",
                               "--benchmark_enable_random_interleaving=true"},
                              flags))
        return 1;

    for (const std::string& name : wanted)
        if (std::none_of(std::begin(kSceneSpecs), std::end(kSceneSpecs),
                         [&](const SceneSpec& spec) { return name == spec.name; })) {
            std::fprintf(stderr, "raster_bench: unknown scene '%s' in --scenes (teapot, organic, icosphere, "
                                 "occlusion)\n", name.c_str());
            return 2;
        }
    std::vector<std::unique_ptr<BenchScene>> scenes = load_scenes(wanted);
    if (scenes.empty()) {
        std::fprintf(stderr, "raster_bench: no scene to measure\n");
        return 2;
    }

    for (const auto& s : scenes)
        for (const RasterCase& c : kRasterCases)
            benchmark::RegisterBenchmark(raster_name(*s, c).c_str(), bm_raster, s.get(), c)
                ->Unit(benchmark::kMillisecond)
                ->MeasureProcessCPUTime()
                ->UseRealTime();

    for (const auto& s : scenes)
        benchmark::RegisterBenchmark(floor_name(*s).c_str(), bm_bandwidth_floor, s.get())
            ->Unit(benchmark::kMillisecond)
            ->MeasureProcessCPUTime()
            ->UseRealTime();

    for (const auto& s : scenes)
        benchmark::RegisterBenchmark(oracle_name(*s).c_str(), bm_oracle, s.get())
            ->Unit(benchmark::kMillisecond)
            ->MeasureProcessCPUTime()
            ->UseRealTime();

    bool checked = true;
    std::string llvmpipe_absent;
#ifdef RASTER_HAVE_OSMESA
    if (LlvmpipePeer* p = scenes.front()->llvmpipe())
        std::printf("llvmpipe peer: %s (LP_NUM_THREADS=%s)\n", p->renderer().c_str(), std::getenv("LP_NUM_THREADS"));
    for (const auto& s : scenes) {
        checked = cross_check(*s) && checked;
        for (int samples : kLlvmpipeSamples)
            benchmark::RegisterBenchmark(llvmpipe_name(*s, samples).c_str(), bm_llvmpipe, s.get(), samples)
                ->Unit(benchmark::kMillisecond)
                ->MeasureProcessCPUTime()
                ->UseRealTime();
    }
    std::printf("\n");
#else
    llvmpipe_absent = "not built: OSMesa (libosmesa6-dev) was not found when configuring";
    std::printf("llvmpipe peer: %s; only raster is measured\n\n", llvmpipe_absent.c_str());
#endif

    SummaryReporter reporter(isatty(fileno(stdout)) ? benchmark::ConsoleReporter::OO_ColorTabular
                                                    : benchmark::ConsoleReporter::OO_Tabular);
    benchmark::RunSpecifiedBenchmarks(&reporter);
    print_summary(reporter, scenes, llvmpipe_absent);
    benchmark::Shutdown();
    scenes.clear();  // the llvmpipe peers' OSMesa contexts go before OSMesa's own teardown at exit
    if (!checked) {
        std::printf("cross-check FAILED: an llvmpipe image does not match raster's; that comparison is not valid\n");
        return 1;
    }
    return 0;
}
