// raster's own benchmark: the timed frames and the stage split of the last one as counters.
#include "bench/raster_benchmark.h"

namespace raster_bench {

raster::RenderOptions render_options(bool keep_visibility) {
    raster::RenderOptions options;
    options.threads = kThreads;
    options.keep_visibility = keep_visibility;
    return options;
}

std::string raster_name(const BenchScene& s, const RasterCase& c) {
    return "BM_Raster/" + s.name + "/samples:" + std::to_string(c.samples) + (c.msaa ? "/msaa" : "");
}

void bm_raster(benchmark::State& state, const BenchScene* s, RasterCase c) {
    const raster::Scene scene = with_samples(s->scene, c.samples, c.msaa);
    const raster::RenderOptions options = render_options(false);
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

}  // namespace raster_bench
