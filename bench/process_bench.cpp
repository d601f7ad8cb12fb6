// process_bench: the whole process, as a user runs it, for one frame: `raster render SCENE -o OUT.png --threads 2`
// against llvmpipe_render (load, one llvmpipe frame through OSMesa with 2 threads, the same PNG encoder), each
// started fresh every iteration; Google Benchmark medians and their ratio (target: raster at most 0.3x).
#include <benchmark/benchmark.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "bench/benchmark_flags.h"

extern char** environ;

namespace {

struct Case {
    std::string scene_name, scene_path;
};

// Runs argv to completion; its exit status, or -1 when it could not be started or did not exit normally.
int run(const std::vector<std::string>& argv) {
    std::vector<char*> args;
    for (const std::string& arg : argv) args.push_back(const_cast<char*>(arg.c_str()));
    args.push_back(nullptr);
    pid_t pid;
    if (posix_spawn(&pid, args[0], nullptr, nullptr, args.data(), environ) != 0) return -1;
    int status = 0;
    if (waitpid(pid, &status, 0) != pid || !WIFEXITED(status)) return -1;
    return WEXITSTATUS(status);
}

void bm_process(benchmark::State& state, std::vector<std::string> argv) {
    for (auto _ : state) {
        const int status = run(argv);
        if (status != 0) {
            state.SkipWithError(("exit status " + std::to_string(status) + " from " + argv[0]).c_str());
            break;
        }
    }
}

class MedianCollector : public benchmark::ConsoleReporter {
public:
    std::map<std::string, double> median_ms;
    void ReportRuns(const std::vector<Run>& runs) override {
        ConsoleReporter::ReportRuns(runs);
        for (const Run& run : runs)
            if (run.aggregate_name == "median" && !run.error_occurred)
                median_ms[run.run_name.function_name] = run.GetAdjustedRealTime();
    }
};

}  // namespace

int main(int argc, char** argv) {
    if (!raster_bench::initialize_benchmark(argv[0],
                                            {"--benchmark_repetitions=7", "--benchmark_report_aggregates_only=true",
                                             "--benchmark_enable_random_interleaving=true"},
                                            std::vector<char*>(argv + 1, argv + argc)))
        return 1;

    const std::filesystem::path out_dir =
        std::filesystem::temp_directory_path() / ("process_bench-" + std::to_string(::getpid()));
    std::filesystem::create_directories(out_dir);
    const Case cases[] = {{"teapot", RASTER_SOURCE_DIR "/corpus/scenes/teapot.yaml"},
                          {"icosphere", RASTER_BENCH_SCENE_DIR "/icosphere.yaml"}};
    for (const Case& c : cases) {
        const std::string out = (out_dir / (c.scene_name + ".png")).string();
        benchmark::RegisterBenchmark(("BM_Process/raster/" + c.scene_name).c_str(), bm_process,
                                     std::vector<std::string>{RASTER_PROGRAM, "render", c.scene_path, "-o", out,
                                                              "--threads", "2"})
            ->Unit(benchmark::kMillisecond)
            ->UseRealTime();
        benchmark::RegisterBenchmark(("BM_Process/llvmpipe/" + c.scene_name).c_str(), bm_process,
                                     std::vector<std::string>{LLVMPIPE_RENDER_PROGRAM, c.scene_path, out})
            ->Unit(benchmark::kMillisecond)
            ->UseRealTime();
    }
    MedianCollector collector;
    benchmark::RunSpecifiedBenchmarks(&collector);
    benchmark::Shutdown();
    std::filesystem::remove_all(out_dir);

    std::printf("\nWhole process for one frame, medians (target: raster at most 0.3x llvmpipe's):\n");
    std::printf("  %-10s %12s %12s %8s\n", "scene", "raster ms", "llvmpipe ms", "ratio");
    for (const Case& c : cases) {
        const auto raster = collector.median_ms.find("BM_Process/raster/" + c.scene_name);
        const auto llvmpipe = collector.median_ms.find("BM_Process/llvmpipe/" + c.scene_name);
        if (raster == collector.median_ms.end() || llvmpipe == collector.median_ms.end()) continue;
        std::printf("  %-10s %12.1f %12.1f %8.2f\n", c.scene_name.c_str(), raster->second, llvmpipe->second,
                    raster->second / llvmpipe->second);
    }
    return 0;
}
