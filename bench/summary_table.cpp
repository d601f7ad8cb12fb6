// The closing tables: median times per frame, raster/llvmpipe ratios, the targets, and raster against the oracle.
#include "bench/summary_table.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>

#include "bench/bandwidth_floor.h"
#include "bench/peer_benchmarks.h"
#include "bench/raster_benchmark.h"

namespace raster_bench {

namespace {

// The reported targets (not asserted; issue 34): raster at most 0.35x llvmpipe's frame time on these at 1 sample,
// 0.25x at 4 (MSAA against MSAA), and its 16-sample MSAA at least 30x faster than the oracle's visibility.
constexpr const char* kTargetScenes[] = {"teapot", "icosphere"};

std::string format_number(double value) {
    if (std::isnan(value)) return "-";
    char text[32];
    std::snprintf(text, sizeof text, "%.2f", value);
    return text;
}

bool llvmpipe_has(int samples) {
    return std::find(std::begin(kLlvmpipeSamples), std::end(kLlvmpipeSamples), samples) != std::end(kLlvmpipeSamples);
}

// Median raster/llvmpipe ratio of one raster case on one clock; NaN when either did not run.
double ratio(const SummaryReporter& reporter, const BenchScene& s, const RasterCase& c, SummaryReporter::Clock clock) {
    const double mine = reporter.median_ms(raster_name(s, c), clock);
    const double theirs = reporter.median_ms(llvmpipe_name(s, c.samples), clock);
    return theirs > 0 ? mine / theirs : NAN;
}

}  // namespace

void SummaryReporter::ReportRuns(const std::vector<Run>& runs) {
    for (const Run& run : runs) {
        if (run.error_occurred) continue;
        const double to_ms = 1e3 / benchmark::GetTimeUnitMultiplier(run.time_unit);
        const std::array<double, 2> ms{run.GetAdjustedRealTime() * to_ms, run.GetAdjustedCPUTime() * to_ms};
        const std::string& name = run.run_name.function_name;
        if (run.run_type == Run::RT_Aggregate && run.aggregate_name == "median") medians_[name] = ms;
        else if (run.run_type == Run::RT_Iteration) runs_[name].push_back(ms);
    }
    ConsoleReporter::ReportRuns(runs);
}

double SummaryReporter::median_ms(const std::string& name, Clock clock) const {
    if (auto it = medians_.find(name); it != medians_.end()) return it->second[clock];
    auto it = runs_.find(name);
    if (it == runs_.end() || it->second.empty()) return NAN;
    std::vector<double> v;
    for (const auto& ms : it->second) v.push_back(ms[clock]);
    std::sort(v.begin(), v.end());
    const size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

void print_summary(const SummaryReporter& reporter, const std::vector<std::unique_ptr<BenchScene>>& scenes,
                   const std::string& llvmpipe_absent) {
    std::printf("\nMedians per frame, %d threads each%s\n", kThreads,
                llvmpipe_absent.empty() ? "" : (" (llvmpipe: " + llvmpipe_absent + ")").c_str());
    std::printf("%-10s %9s %8s %-8s %10s %12s %16s   %10s %12s %9s\n", "scene", "triangles", "size", "samples",
                "raster ms", "llvmpipe ms", "raster/llvmpipe", "raster cpu", "llvmpipe cpu", "cpu ratio");
    for (const auto& s : scenes) {
        const std::string size = std::to_string(s->scene.settings.width) + "x" + std::to_string(s->scene.settings.height);
        bool first_row = true;
        for (const RasterCase& c : kRasterCases) {
            const bool peer_has = llvmpipe_has(c.samples);
            auto peer = [&](double v) { return peer_has ? format_number(v) : std::string("n/a (4x max)"); };
            const std::string row = std::to_string(c.samples) + (c.msaa ? " msaa" : c.samples > 1 ? " ssaa" : "");
            std::printf("%-10s %9s %8s %-8s %10s %12s %16s   %10s %12s %9s\n", first_row ? s->name.c_str() : "",
                        first_row ? std::to_string(raster::triangle_count(s->scene)).c_str() : "",
                        first_row ? size.c_str() : "", row.c_str(),
                        format_number(reporter.median_ms(raster_name(*s, c), SummaryReporter::wall)).c_str(),
                        peer(reporter.median_ms(llvmpipe_name(*s, c.samples), SummaryReporter::wall)).c_str(),
                        format_number(ratio(reporter, *s, c, SummaryReporter::wall)).c_str(),
                        format_number(reporter.median_ms(raster_name(*s, c), SummaryReporter::cpu)).c_str(),
                        peer(reporter.median_ms(llvmpipe_name(*s, c.samples), SummaryReporter::cpu)).c_str(),
                        format_number(ratio(reporter, *s, c, SummaryReporter::cpu)).c_str());
            first_row = false;
        }
    }
    std::printf("ms: wall time; cpu: CPU time of every thread of the process (less sensitive to other load).\n"
                "ssaa rows shade every sample; msaa rows shade once per pixel per triangle, like llvmpipe's 4x\n"
                "MSAA (resolved by glBlitFramebuffer in its time). Both llvmpipe ratios at 4 samples are against\n"
                "its 4x MSAA.\n");

    // The targets, reported and never asserted: raster/llvmpipe wall-time ratio at most 0.35 at 1 sample and 0.25
    // at 4 samples (MSAA against MSAA).
    struct Target {
        RasterCase c;
        double ratio;
    };
    const Target targets[] = {{{1, false}, 0.35}, {{4, true}, 0.25}};
    std::printf("\nTargets (raster at most 0.35x llvmpipe's frame time at 1 sample, 0.25x at 4, wall medians):\n");
    for (const auto& s : scenes) {
        if (std::none_of(std::begin(kTargetScenes), std::end(kTargetScenes),
                         [&](const char* name) { return s->name == name; }))
            continue;
        for (const Target& target : targets) {
            const RasterCase& c = target.c;
            const double r = ratio(reporter, *s, c, SummaryReporter::wall);
            std::printf("  %-10s %d sample%-6s %6s  %s\n", s->name.c_str(), c.samples,
                        c.msaa ? "s msaa" : "", format_number(r).c_str(),
                        std::isnan(r) ? "not measured" : r <= target.ratio ? "met" : "missed");
        }
    }

    // The memory floor: raster's 1-sample frame over writing its colour and depth once (bandwidth_floor.h).
    std::printf("\nAgainst the memory floor (colour and depth memset once, %d threads, 1 sample):\n", kThreads);
    std::printf("  %-10s %10s %10s %12s\n", "scene", "raster ms", "floor ms", "raster/floor");
    for (const auto& s : scenes) {
        const double frame = reporter.median_ms(raster_name(*s, {1, false}), SummaryReporter::wall);
        const double floor = reporter.median_ms(floor_name(*s), SummaryReporter::wall);
        std::printf("  %-10s %10s %10s %11sx\n", s->name.c_str(), format_number(frame).c_str(),
                    format_number(floor).c_str(), format_number(frame / floor).c_str());
    }

    // Against the Embree oracle at 16 samples: how many times faster raster's frame is (target: at least 30x with MSAA).
    std::printf("\nAgainst the Embree oracle at %d samples (its visibility only; target: raster's MSAA at least 30x faster):\n",
                kOracleSamples);
    std::printf("  %-10s %10s %14s %14s %12s %12s\n", "scene", "oracle ms", "raster ssaa ms", "raster msaa ms",
                "ssaa speedup", "msaa speedup");
    for (const auto& s : scenes) {
        const double oracle = reporter.median_ms(oracle_name(*s), SummaryReporter::wall);
        const double ssaa = reporter.median_ms(raster_name(*s, {kOracleSamples, false}), SummaryReporter::wall);
        const double msaa = reporter.median_ms(raster_name(*s, {kOracleSamples, true}), SummaryReporter::wall);
        const double speedup = oracle / msaa;
        std::printf("  %-10s %10s %14s %14s %11sx %11sx  %s\n", s->name.c_str(), format_number(oracle).c_str(),
                    format_number(ssaa).c_str(), format_number(msaa).c_str(), format_number(oracle / ssaa).c_str(),
                    format_number(speedup).c_str(),
                    std::isnan(speedup) ? "not measured" : speedup >= 30.0 ? "met" : "missed");
    }
}

}  // namespace raster_bench
