// raster_bench: raster's frame time on the bundled teapot and, in the same run, Mesa llvmpipe (OSMesa) drawing
// the same triangles with the same camera and per-fragment Blinn-Phong; ends with a median-time comparison table.
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "raster/image.h"
#include "raster/render.h"
#include "raster/scene.h"
#include "raster/scene_loader.h"

#ifdef RASTER_HAVE_OSMESA
#include "llvmpipe_peer.h"
#endif

namespace {

constexpr int kThreads = 2;  // raster's RenderOptions::threads and llvmpipe's LP_NUM_THREADS
constexpr const char* kScenePath = RASTER_SOURCE_DIR "/corpus/scenes/teapot.yaml";
// raster's cases: SSAA (every sample shaded, the teapot scene's setting) at 1, 4 and 16 samples, and 4-sample
// MSAA (shaded once per pixel per triangle), the like-for-like partner of llvmpipe's 4x MSAA.
struct RasterCase {
    int samples;
    bool msaa;
};
constexpr RasterCase kRasterCases[] = {{1, false}, {4, false}, {4, true}, {16, false}};
constexpr int kLlvmpipeSamples[] = {1, 4};  // llvmpipe's multisampling stops at 4x

const raster::Scene& teapot() {
    static const raster::Scene scene = raster::load_scene(kScenePath);
    return scene;
}

raster::Scene teapot_with_samples(int samples, bool msaa = false) {
    raster::Scene scene = teapot();
    scene.settings.samples = samples;
    scene.settings.pattern = raster::SamplePattern::standard;
    scene.settings.msaa = msaa;
    return scene;
}

raster::RenderOptions render_options() {
    raster::RenderOptions options;
    options.threads = kThreads;
    return options;
}

std::string raster_name(const RasterCase& c) {
    return "BM_Raster/teapot/samples:" + std::to_string(c.samples) + (c.msaa ? "/msaa" : "");
}
std::string llvmpipe_name(int samples) { return "BM_Llvmpipe/teapot/samples:" + std::to_string(samples); }

void bm_raster(benchmark::State& state, RasterCase c) {
    const raster::Scene scene = teapot_with_samples(c.samples, c.msaa);
    const raster::RenderOptions options = render_options();
    raster::RenderStats stats;
    raster::RenderResult result;  // reused frame to frame, as llvmpipe reuses its framebuffer
    for (auto _ : state) {
        raster::render_into(scene, options, result);
        benchmark::DoNotOptimize(result.image.pixels.data());
        stats = result.stats;
    }
    state.counters["triangles"] = static_cast<double>(stats.triangles);
    state.counters["covered_samples"] = static_cast<double>(stats.covered_samples);
    // raster's own stage split of the last frame: what the vertex stage (redone every frame; llvmpipe gets the
    // world-space vertices and normals uploaded once) and the rest cost.
    state.counters["ms_vertex"] = stats.ms_vertex;
    state.counters["ms_setup"] = stats.ms_setup;
    state.counters["ms_raster"] = stats.ms_raster;
    state.counters["ms_shade"] = stats.ms_shade;
}

#ifdef RASTER_HAVE_OSMESA
using raster_bench::LlvmpipePeer;

// One OSMesa context for the whole run, created on first use; null with peer_error() set when it cannot be.
std::string& peer_error() {
    static std::string error;
    return error;
}

LlvmpipePeer* peer() {
    static std::unique_ptr<LlvmpipePeer> instance = [] {
        try {
            return std::make_unique<LlvmpipePeer>(teapot(), kThreads);
        } catch (const std::exception& e) {
            peer_error() = e.what();
            return std::unique_ptr<LlvmpipePeer>();
        }
    }();
    return instance.get();
}

void bm_llvmpipe(benchmark::State& state, int samples) {
    LlvmpipePeer* p = peer();
    if (!p) {
        state.SkipWithError(peer_error().c_str());
        return;
    }
    try {
        p->set_samples(samples);
        p->draw_frame();  // untimed: llvmpipe compiles its shader variants on the first draw
    } catch (const std::exception& e) {
        state.SkipWithError(e.what());
        return;
    }
    for (auto _ : state) p->draw_frame();
    state.counters["triangles"] = static_cast<double>(p->triangles());
}

// Once, untimed: the two images must show the same thing, or the timings compare different work.
// At 1 sample, llvmpipe's non-background pixels against raster's covered samples (within 3%), the pixels the
// two disagree on, and the colour difference; at 4 samples the colour difference of the resolved MSAA images.
bool cross_check() {
    LlvmpipePeer* p = peer();
    if (!p) {
        std::printf("cross-check: llvmpipe peer unavailable: %s\n", peer_error().c_str());
        return false;
    }
    std::printf("llvmpipe peer: %s (LP_NUM_THREADS=%s)\n", p->renderer().c_str(), std::getenv("LP_NUM_THREADS"));
    const glm::vec3 bg = teapot().settings.background;
    const uint8_t background[3] = {raster::to_byte(bg.x), raster::to_byte(bg.y), raster::to_byte(bg.z)};
    bool ok = true;
    for (int samples : kLlvmpipeSamples) {
        // At 4 samples raster's MSAA mode, which like llvmpipe's MSAA shades once per pixel per triangle.
        const raster::RenderResult mine = raster::render(teapot_with_samples(samples, samples > 1), render_options());
        p->set_samples(samples);
        p->draw_frame();
        const std::vector<uint8_t> theirs = p->image_top_down();
        const size_t pixels = static_cast<size_t>(mine.image.width) * mine.image.height;
        size_t mine_touched = 0, theirs_covered = 0, disagree = 0, both = 0, max_diff = 0, within_one = 0;
        double diff_sum = 0;
        for (size_t i = 0; i < pixels; ++i) {
            const uint8_t* a = &mine.image.pixels[i * mine.image.channels];
            const uint8_t* b = &theirs[i * 4];
            bool a_covered = false;  // any of the pixel's samples
            for (int s = 0; s < samples; ++s) a_covered |= mine.visibility.triangle[i * samples + s] != raster::kNoTriangle;
            const bool b_covered = b[0] != background[0] || b[1] != background[1] || b[2] != background[2];
            mine_touched += a_covered;
            theirs_covered += b_covered;
            disagree += a_covered != b_covered;
            size_t diff = 0;
            for (int c = 0; c < 3; ++c) diff = std::max<size_t>(diff, std::abs(int(a[c]) - int(b[c])));
            if (samples == 1 && !(a_covered && b_covered)) continue;  // 1 sample: colour where both draw
            ++both;
            diff_sum += double(diff);
            max_diff = std::max(max_diff, diff);
            within_one += diff <= 1;
        }
        std::printf("cross-check, %d sample%s:\n", samples, samples == 1 ? "" : "s (both MSAA)");
        if (samples == 1) {
            const double relative = mine.stats.covered_samples
                                        ? (double(theirs_covered) - double(mine.stats.covered_samples)) /
                                              double(mine.stats.covered_samples)
                                        : 1.0;
            const bool close = std::abs(relative) <= 0.03;
            ok = ok && close;
            std::printf("  raster covered samples           %zu\n", mine.stats.covered_samples);
            std::printf("  llvmpipe non-background pixels   %zu  (%+.3f%%, %s)\n", theirs_covered,
                        100.0 * relative, close ? "within 3%" : "MISMATCH: over 3%");
        } else {
            std::printf("  raster pixels with a sample      %zu\n", mine_touched);
            std::printf("  llvmpipe non-background pixels   %zu\n", theirs_covered);
        }
        std::printf("  pixels drawn by only one         %zu\n", disagree);
        std::printf("  colour (%s): mean |diff| %.3f, max %zu, %.2f%% within 1/255\n",
                    samples == 1 ? "pixels both draw" : "all pixels", both ? diff_sum / double(both) : 0.0, max_diff,
                    both ? 100.0 * double(within_one) / double(both) : 0.0);
    }
    std::printf("\n");
    std::fflush(stdout);
    return ok;
}
#endif

// The console reporter, also keeping each benchmark's median wall and process CPU time per frame (or, without
// repetitions, the median over its runs) for the closing table.
class SummaryReporter : public benchmark::ConsoleReporter {
public:
    using ConsoleReporter::ConsoleReporter;

    enum Clock { wall = 0, cpu = 1 };

    void ReportRuns(const std::vector<Run>& runs) override {
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

    // Median milliseconds per frame; NaN when the benchmark did not run.
    double median_ms(const std::string& name, Clock clock) const {
        if (auto it = medians_.find(name); it != medians_.end()) return it->second[clock];
        auto it = runs_.find(name);
        if (it == runs_.end() || it->second.empty()) return NAN;
        std::vector<double> v;
        for (const auto& ms : it->second) v.push_back(ms[clock]);
        std::sort(v.begin(), v.end());
        const size_t n = v.size();
        return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
    }

private:
    std::map<std::string, std::array<double, 2>> medians_;
    std::map<std::string, std::vector<std::array<double, 2>>> runs_;
};

std::string format_number(double value) {
    if (std::isnan(value)) return "-";
    char text[32];
    std::snprintf(text, sizeof text, "%.2f", value);
    return text;
}

void print_summary(const SummaryReporter& reporter, const std::string& llvmpipe_absent) {
    const raster::Scene& scene = teapot();
    std::printf("\nMedians per frame, teapot %dx%d, %zu triangles, %d threads each%s\n", scene.settings.width,
                scene.settings.height, raster::triangle_count(scene), kThreads,
                llvmpipe_absent.empty() ? "" : (" (llvmpipe: " + llvmpipe_absent + ")").c_str());
    std::printf("%-8s %10s %12s %16s   %10s %12s %8s\n", "samples", "raster ms", "llvmpipe ms", "raster/llvmpipe",
                "raster cpu", "llvmpipe cpu", "cpu ratio");
    for (const RasterCase& c : kRasterCases) {
        const int samples = c.samples;
        const bool peer_has = std::find(std::begin(kLlvmpipeSamples), std::end(kLlvmpipeSamples), samples) !=
                              std::end(kLlvmpipeSamples);
        double values[2][2];  // [clock][raster, llvmpipe]
        for (int clock : {SummaryReporter::wall, SummaryReporter::cpu}) {
            values[clock][0] = reporter.median_ms(raster_name(c), SummaryReporter::Clock(clock));
            values[clock][1] = reporter.median_ms(llvmpipe_name(samples), SummaryReporter::Clock(clock));
        }
        auto ratio = [](const double* v) { return v[1] > 0 ? v[0] / v[1] : NAN; };
        const std::string absent = peer_has ? "-" : "n/a (4x max)";
        auto peer = [&](double v) { return peer_has ? format_number(v) : absent; };
        const std::string row = std::to_string(samples) + (c.msaa ? " msaa" : "");
        std::printf("%-8s %10s %12s %16s   %10s %12s %8s\n", row.c_str(), format_number(values[0][0]).c_str(),
                    peer(values[0][1]).c_str(), format_number(ratio(values[0])).c_str(),
                    format_number(values[1][0]).c_str(), peer(values[1][1]).c_str(),
                    format_number(ratio(values[1])).c_str());
    }
    std::printf("ms: wall time; cpu: CPU time of every thread of the process (less sensitive to other load).\n"
                "raster rows without msaa shade every sample (SSAA, the scene's setting); \"4 msaa\" shades once\n"
                "per pixel per triangle like llvmpipe's 4x MSAA (resolved by glBlitFramebuffer in its time).\n");
}

}  // namespace

int main(int argc, char** argv) {
    // Defaults first so that the user's flags, parsed later, win. Interleaving the repetitions of raster and
    // llvmpipe in random order spreads slow drifts in machine load over both instead of charging one.
    std::string repetitions = "--benchmark_repetitions=7";
    std::string aggregates_only = "--benchmark_report_aggregates_only=true";
    std::string interleave = "--benchmark_enable_random_interleaving=true";
    std::vector<char*> args{argv[0], repetitions.data(), aggregates_only.data(), interleave.data()};
    for (int i = 1; i < argc; ++i) args.push_back(argv[i]);
    int arg_count = static_cast<int>(args.size());
    args.push_back(nullptr);
    benchmark::Initialize(&arg_count, args.data());
    if (benchmark::ReportUnrecognizedArguments(arg_count, args.data())) return 1;

    try {
        std::printf("scene: %s (%zu triangles)\n", kScenePath, raster::triangle_count(teapot()));
    } catch (const std::exception& e) {
        std::fprintf(stderr, "raster_bench: %s\n", e.what());
        return 2;
    }

    for (const RasterCase& c : kRasterCases)
        benchmark::RegisterBenchmark(raster_name(c).c_str(), bm_raster, c)
            ->Unit(benchmark::kMillisecond)
            ->MeasureProcessCPUTime()
            ->UseRealTime();

    bool checked = true;
    std::string llvmpipe_absent;
#ifdef RASTER_HAVE_OSMESA
    checked = cross_check();
    for (int samples : kLlvmpipeSamples)
        benchmark::RegisterBenchmark(llvmpipe_name(samples).c_str(), bm_llvmpipe, samples)
            ->Unit(benchmark::kMillisecond)
            ->MeasureProcessCPUTime()
            ->UseRealTime();
#else
    llvmpipe_absent = "not built: OSMesa (libosmesa6-dev) was not found when configuring";
    std::printf("llvmpipe peer: %s; only raster is measured\n\n", llvmpipe_absent.c_str());
#endif

    SummaryReporter reporter(isatty(fileno(stdout)) ? benchmark::ConsoleReporter::OO_ColorTabular
                                                    : benchmark::ConsoleReporter::OO_Tabular);
    benchmark::RunSpecifiedBenchmarks(&reporter);
    print_summary(reporter, llvmpipe_absent);
    benchmark::Shutdown();
    if (!checked) {
        std::printf("cross-check FAILED: the llvmpipe image does not match raster's; the comparison is not valid\n");
        return 1;
    }
    return 0;
}
