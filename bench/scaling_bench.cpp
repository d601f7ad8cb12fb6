// scaling_bench: how raster's frame time grows with the triangle count (a sphere of 1k to 1M triangles covering
// the same screen area at 800x800) and with the resolution (the 81,920-triangle sphere at 256^2 to 4096^2).
// Google Benchmark medians, then the fit time = a + b triangles + c covered samples, each point's distance from
// it, and an SVG of both sweeps (--svg=FILE, default scaling.svg).
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <string>
#include <vector>

#include "bench/benchmark_flags.h"
#include "bench/scaling_plot.h"
#include "raster/core/file_io.h"
#include "raster/frame/render.h"

namespace {

using raster_bench::ScalingPoint;

// A unit sphere of `stacks` x `slices` quads (two triangles each; the poles' rows are fans of one triangle),
// normals equal to positions.
raster::MeshData uv_sphere(int stacks, int slices) {
    raster::MeshData mesh;
    for (int i = 0; i <= stacks; ++i) {
        const double theta = M_PI * i / stacks;
        for (int j = 0; j < slices; ++j) {
            const double phi = 2.0 * M_PI * j / slices;
            const glm::vec3 p(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
            mesh.positions.push_back(p);
            mesh.normals.push_back(p);
        }
    }
    auto at = [&](int i, int j) { return static_cast<uint32_t>(i * slices + (j % slices)); };
    for (int i = 0; i < stacks; ++i)
        for (int j = 0; j < slices; ++j) {
            if (i > 0) mesh.triangles.push_back({{at(i, j), at(i, j + 1), at(i + 1, j)}});
            if (i + 1 < stacks) mesh.triangles.push_back({{at(i, j + 1), at(i + 1, j + 1), at(i + 1, j)}});
        }
    return mesh;
}

// The bench scenes' look (Blinn-Phong, two lights), the sphere filling the middle of a square view.
raster::Scene sphere_scene(int triangles, int size) {
    const int stacks = std::max(4, static_cast<int>(std::lround(std::sqrt(triangles / 4.0))));
    raster::Scene scene;
    scene.settings.width = scene.settings.height = size;
    scene.settings.background = glm::vec3(0.08f, 0.08f, 0.1f);
    scene.camera.eye = glm::vec3(0.0f, 1.2f, 3.4f);
    scene.camera.fov_y_degrees = 40.0f;
    scene.camera.near = 1.0f;
    scene.camera.far = 10.0f;
    scene.lights = {{{4, 5, 4}, {1, 1, 1}, 0.9f, false, false}, {{-5, 1, 3}, {0.5f, 0.6f, 0.9f}, 0.4f, false, false}};
    raster::SceneMesh mesh;
    mesh.data = raster::shared_mesh_data(uv_sphere(stacks, 2 * stacks));
    mesh.material.color = glm::vec3(0.3f, 0.55f, 0.8f);
    mesh.material.exponent = 60.0f;
    mesh.source = "generated sphere";
    scene.meshes.push_back(std::move(mesh));
    return scene;
}

void bm_frame(benchmark::State& state, const raster::Scene* scene) {
    raster::RenderOptions options;
    options.threads = 2;
    options.keep_visibility = false;
    raster::RenderResult result;
    for (auto _ : state) {
        raster::render_into(*scene, options, result);
        benchmark::DoNotOptimize(result.image.pixels.data());
    }
    state.counters["triangles"] = static_cast<double>(result.stats.triangles);
    state.counters["pixels"] = static_cast<double>(result.stats.samples);
    state.counters["covered_samples"] = static_cast<double>(result.stats.covered_samples);
}

// Keeps the median of every benchmark, and its counters, while the console shows the usual table.
class MedianCollector : public benchmark::ConsoleReporter {
public:
    std::map<std::string, ScalingPoint> medians;
    void ReportRuns(const std::vector<Run>& runs) override {
        ConsoleReporter::ReportRuns(runs);
        for (const Run& run : runs) {
            if (run.aggregate_name != "median") continue;
            const std::string name = run.run_name.function_name;
            ScalingPoint p;
            p.sweep = name.rfind("BM_Triangles", 0) == 0 ? "triangles" : "resolution";
            p.triangles = run.counters.at("triangles");
            p.pixels = run.counters.at("pixels");
            p.covered_samples = run.counters.at("covered_samples");
            p.ms = run.GetAdjustedRealTime();  // in the benchmark's unit, milliseconds
            medians[name] = p;
        }
    }
};

}  // namespace

int main(int argc, char** argv) {
    std::string svg_path = "scaling.svg";
    std::vector<char*> flags;
    for (int i = 1; i < argc; ++i) {
        if (std::strncmp(argv[i], "--svg=", 6) == 0) svg_path = argv[i] + 6;
        else flags.push_back(argv[i]);
    }
    if (!raster_bench::initialize_benchmark(
            argv[0], {"--benchmark_repetitions=5", "--benchmark_report_aggregates_only=true"}, flags))
        return 1;

    std::vector<std::unique_ptr<raster::Scene>> scenes;
    auto add = [&](const std::string& name, int triangles, int size) {
        scenes.push_back(std::make_unique<raster::Scene>(sphere_scene(triangles, size)));
        benchmark::RegisterBenchmark(name.c_str(), bm_frame, scenes.back().get())
            ->Unit(benchmark::kMillisecond)
            ->UseRealTime();
    };
    for (int triangles : {1000, 4000, 16000, 64000, 256000, 1000000})
        add("BM_Triangles/" + std::to_string(triangles), triangles, 800);
    for (int size : {256, 512, 1024, 2048, 4096}) add("BM_Resolution/" + std::to_string(size), 81920, size);

    MedianCollector collector;
    benchmark::RunSpecifiedBenchmarks(&collector);
    benchmark::Shutdown();
    std::vector<ScalingPoint> points;
    for (const auto& [name, point] : collector.medians) points.push_back(point);
    if (points.size() < 3) {
        std::fprintf(stderr, "scaling_bench: %zu medians measured, 3 needed for the fit\n", points.size());
        return 2;
    }
    const raster_bench::ScalingFit fit = raster_bench::fit_scaling(points);
    std::printf("\nfit: %.3f ms + %.4f us per triangle + %.3f ns per covered sample\n", fit.fixed_ms,
                fit.ms_per_triangle * 1e3, fit.ms_per_sample * 1e6);
    std::printf("%-10s %10s %12s %14s %10s %10s %8s\n", "sweep", "triangles", "pixels", "covered", "ms", "fit ms",
                "ratio");
    for (const ScalingPoint& p : points)
        std::printf("%-10s %10.0f %12.0f %14.0f %10.2f %10.2f %8.2f\n", p.sweep.c_str(), p.triangles, p.pixels,
                    p.covered_samples, p.ms, fit.predict(p), p.ms / fit.predict(p));
    try {
        raster::write_file_atomically(svg_path, raster_bench::scaling_svg(points, fit, "raster frame time, 2 threads, 1 sample, Blinn-Phong"));
    } catch (const std::exception& e) {
        std::fprintf(stderr, "scaling_bench: %s\n", e.what());
        return 1;
    }
    std::printf("wrote %s\n", svg_path.c_str());
    return 0;
}
