// The rasterizer pipeline: runs each stage in order on plain structs and records what it did.
#include "raster/pipeline/render.h"

#include "raster/pipeline/tiled_renderer.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>

#include <glm/geometric.hpp>

#include "raster/pipeline/clip.h"
#include "raster/core/errors.h"
#include "raster/core/parallel.h"
#include "raster/pipeline/reference_rasterizer.h"
#include "raster/pipeline/resolve.h"
#include "raster/pipeline/sample_pattern.h"
#include "raster/pipeline/setup.h"
#include "raster/pipeline/shade.h"
#include "raster/pipeline/vertex_stage.h"

namespace raster {
namespace {

using Clock = std::chrono::steady_clock;


constexpr size_t kSetupChunk = 4096;

}  // namespace

void set_up_triangles_into(const Scene& scene, const TransformedScene& geometry, int threads,
                           const PipelineStages& stages, RenderStats& stats, RenderWorkspace& workspace) {
    // Clip and set up in chunks of triangles; concatenating the chunks in order keeps the draw order.
    const RenderSettings& settings = scene.settings;
    const ClipVolume volume = clip_volume_for(scene.camera, settings);
    const SetupParams setup_params = setup_params_for(settings);
    const size_t chunks = (geometry.triangles.size() + kSetupChunk - 1) / kSetupChunk;
    auto& chunk_setups = workspace.chunk_setups;
    chunk_setups.resize(chunks);
    std::vector<size_t> chunk_clipped(chunks, 0);
    parallel_for(chunks, threads, [&](size_t chunk) {
        const size_t begin = chunk * kSetupChunk;
        const size_t end = std::min(geometry.triangles.size(), begin + kSetupChunk);
        auto& out = chunk_setups[chunk];
        out.clear();
        out.reserve(end - begin);
        for (size_t tri = begin; tri < end; ++tri) {
            const TriangleIndices& v = geometry.triangles[tri];
            if (settings.cull_backfaces &&
                !stages.faces_front(geometry.clip[v.v[0]], geometry.clip[v.v[1]], geometry.clip[v.v[2]]))
                continue;
            const ClippedPolygon polygon =
                stages.clip(geometry.clip[v.v[0]], geometry.clip[v.v[1]], geometry.clip[v.v[2]], volume);
            chunk_clipped[chunk] += polygon.clipped;
            stages.setup(polygon, static_cast<uint32_t>(tri), setup_params, out);
        }
    });
    std::vector<TriangleSetup>& setups = workspace.setups;
    setups.clear();
    for (size_t chunk = 0; chunk < chunks; ++chunk) {
        setups.insert(setups.end(), chunk_setups[chunk].begin(), chunk_setups[chunk].end());
        stats.clipped += chunk_clipped[chunk];
    }
    stats.rasterized = setups.size();
}

std::vector<TriangleSetup> set_up_triangles(const Scene& scene, const TransformedScene& geometry, int threads,
                                            const PipelineStages& stages, RenderStats& stats) {
    RenderWorkspace workspace;
    set_up_triangles_into(scene, geometry, threads, stages, stats, workspace);
    return std::move(workspace.setups);
}

double milliseconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

TransformedScene run_vertex_stage_timed(const Scene& scene, const PipelineStages& stages, RenderStats& stats) {
    const auto start = Clock::now();
    TransformedScene geometry = stages.vertex(scene, vertex_stage_needs(scene.settings.shading));
    stats.triangles = geometry.triangles.size();
    stats.ms_vertex = milliseconds_since(start);
    return geometry;
}

ResolveParams resolve_params_for(const Scene& scene, const RenderOptions& options) {
    ResolveParams params;
    params.msaa = scene.settings.msaa;
    params.background = scene.settings.background;
    params.alpha = options.alpha;
    params.threads = options.threads;
    return params;
}

RenderResult render(const Scene& scene, const RenderOptions& options, const PipelineStages& stages) {
    RenderResult result;
    render_into(scene, options, result, stages);
    return result;
}

void render_into(const Scene& scene, const RenderOptions& options, RenderResult& result, const PipelineStages& stages) {
    if (options.path == RasterPath::tiled && stages.rasterize == PipelineStages{}.rasterize) {
        render_tiled_into(scene, options, result, stages);
        return;
    }
    const auto start = Clock::now();
    const RenderSettings& settings = scene.settings;
    result.stats = RenderStats{};
    RenderStats& stats = result.stats;

    const TransformedScene geometry = run_vertex_stage_timed(scene, stages, stats);

    auto stage_start = Clock::now();
    set_up_triangles_into(scene, geometry, options.threads, stages, stats, result.workspace);
    const std::vector<TriangleSetup>& setups = result.workspace.setups;
    stats.ms_setup = milliseconds_since(stage_start);

    stage_start = Clock::now();
    RasterParams raster_params;
    raster_params.width = settings.width;
    raster_params.height = settings.height;
    raster_params.snap_bits = settings.snap_bits;
    raster_params.sample_offsets = stages.sample_offsets(settings.samples, settings.pattern);
    raster_params.threads = options.threads;
    stages.rasterize(setups, raster_params, result.visibility);
    stats.samples = result.visibility.size();
    stats.ms_raster = milliseconds_since(stage_start);

    stage_start = Clock::now();
    const Shader shader(scene, geometry, stages.lighting);
    resolve_image(result.visibility, shader, resolve_params_for(scene, options), result.image);
    stats.ms_shade = milliseconds_since(stage_start);

    for (uint32_t id : result.visibility.triangle) stats.covered_samples += id != kNoTriangle;
    stats.ms_total = milliseconds_since(start);
}

}  // namespace raster
