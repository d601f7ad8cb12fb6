// The peers' benchmarks: the Embree oracle's and llvmpipe's frames, and the check that llvmpipe's image is raster's.
#include "bench/peer_benchmarks.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <vector>

#include "bench/raster_benchmark.h"
#include "oracle/reference/ray_caster.h"
#include "oracle/reference/scene_geometry.h"
#include "raster/image/image.h"
#include "raster/image/to_byte.h"
#include "raster/frame/render.h"

namespace raster_bench {

std::string oracle_name(const BenchScene& s) { return "BM_Oracle/" + s.name + "/samples:" + std::to_string(kOracleSamples); }

void bm_oracle(benchmark::State& state, const BenchScene* s) {
    const raster::Scene scene = with_samples(s->scene, kOracleSamples, false);
    const raster::oracle::OracleScene geometry = raster::oracle::oracle_scene(scene);
    raster::oracle::OracleOptions options;
    options.threads = kThreads;
    raster::oracle::SampleBuffer buffer;  // reused frame to frame
    for (auto _ : state) {
        raster::oracle::render_oracle(scene, geometry, options, buffer);
        benchmark::DoNotOptimize(buffer.triangle.data());
    }
}

std::string llvmpipe_name(const BenchScene& s, int samples) {
    return "BM_Llvmpipe/" + s.name + "/samples:" + std::to_string(samples);
}

#ifdef RASTER_HAVE_OSMESA
void bm_llvmpipe(benchmark::State& state, BenchScene* s, int samples) {
    LlvmpipePeer* p = s->llvmpipe();
    if (!p) {
        state.SkipWithError(s->peer_error.c_str());
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

bool cross_check(BenchScene& s) {
    LlvmpipePeer* p = s.llvmpipe();
    if (!p) {
        std::printf("cross-check %s: llvmpipe peer unavailable: %s\n", s.name.c_str(), s.peer_error.c_str());
        return false;
    }
    const glm::vec3 bg = s.scene.settings.background;
    const uint8_t background[3] = {raster::to_byte(bg.x), raster::to_byte(bg.y), raster::to_byte(bg.z)};
    bool ok = true;
    for (int samples : kLlvmpipeSamples) {
        // At 4 samples raster's MSAA mode, which like llvmpipe's MSAA shades once per pixel per triangle.
        const raster::RenderResult mine =
            raster::render(with_samples(s.scene, samples, samples > 1), render_options(true));
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
            for (int k = 0; k < samples; ++k)
                a_covered |= mine.visibility.triangle[i * samples + k] != raster::kNoTriangle;
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
        std::printf("cross-check %s, %d sample%s:\n", s.name.c_str(), samples, samples == 1 ? "" : "s (both MSAA)");
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
    std::fflush(stdout);
    return ok;
}
#endif

}  // namespace raster_bench
