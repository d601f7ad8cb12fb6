// The front end: the timed vertex stage, and culling, clipping and setup in parallel chunks kept in draw order.
#include "raster/pipeline/front_end.h"

#include <algorithm>

#include "raster/core/parallel.h"
#include "raster/core/stopwatch.h"
#include "raster/pipeline/setup_table.h"
#include "raster/pipeline/transparency.h"

namespace raster {
TransformedScene run_vertex_stage_timed(const Scene& scene, const PipelineStages& stages, RenderStats& stats) {
    const auto start = Clock::now();
    TransformedScene geometry = stages.vertex(scene, vertex_stage_needs(scene.settings.shading));
    stats.triangles = geometry.triangles.size();
    stats.ms_vertex = milliseconds_since(start);
    return geometry;
}

namespace {

// Each vertex projected to the screen once, for the triangles no clip plane touches, and whether it is inside the
// clip volume, into `out`; left empty when the stages are not the real clip and setup, whose fused form this is.
void project_vertices(const TransformedScene& geometry, const FrameParams& frame, const PipelineStages& stages,
                      ProjectedVertices& out) {
    out.screen.clear();
    out.inside.clear();
    if (stages.clip != clip_triangle || stages.setup != setup_polygon) return;
    const size_t count = geometry.clip.size();
    out.screen.resize(count);
    out.inside.resize(count);
    const SnapGrid grid = snap_grid(frame);
    constexpr size_t kBatch = 16384;
    parallel_for((count + kBatch - 1) / kBatch, frame.threads, [&](size_t batch) {
        for (size_t i = batch * kBatch; i < std::min(count, (batch + 1) * kBatch); ++i) {
            out.inside[i] = inside_clip_volume(geometry.clip[i], frame.clip);
            if (out.inside[i]) out.screen[i] = project_to_screen(geometry.clip[i], frame, grid);
        }
    });
}

}  // namespace

void set_up_triangles_into(const TransformedScene& geometry, const FrameParams& frame, const PipelineStages& stages,
                           bool cull, RenderStats& stats, RenderWorkspace& workspace) {
    ProjectedVertices& projected = workspace.projected;
    project_vertices(geometry, frame, stages, projected);
    // Clip and set up in chunks of triangles, each into its own list: the chunks in order keep the draw order.
    const size_t chunks = (geometry.triangles.size() + kSetupChunkTriangles - 1) / kSetupChunkTriangles;
    auto& chunk_setups = workspace.setup_chunks;
    chunk_setups.resize(chunks);  // each list keeps its storage from frame to frame
    std::vector<size_t> chunk_clipped(chunks, 0);
    parallel_for(chunks, frame.threads, [&](size_t chunk) {
        const size_t begin = chunk * kSetupChunkTriangles;
        const size_t end = std::min(geometry.triangles.size(), begin + kSetupChunkTriangles);
        auto& out = chunk_setups[chunk];
        out.clear();
        out.reserve(end - begin);
        for (size_t tri = begin; tri < end; ++tri) {
            const TriangleIndices& v = geometry.triangles[tri];
            const glm::vec4 &a = geometry.clip[v.v[0]], &b = geometry.clip[v.v[1]], &c = geometry.clip[v.v[2]];
            if (cull && !stages.faces_front(a, b, c)) continue;
            const auto id = static_cast<uint32_t>(tri);
            if (!projected.inside.empty() && projected.inside[v.v[0]] && projected.inside[v.v[1]] &&
                projected.inside[v.v[2]]) {  // what clip_triangle passes through untouched
                const std::array<const ScreenPoint*, 3> screen = {&projected.screen[v.v[0]], &projected.screen[v.v[1]],
                                                                  &projected.screen[v.v[2]]};
                setup_screen_triangle(screen, {&kCornerBarycentrics[0], &kCornerBarycentrics[1], &kCornerBarycentrics[2]},
                                      id, frame, out);
                continue;
            }
            const ClippedPolygon polygon = stages.clip(a, b, c, frame.clip);
            chunk_clipped[chunk] += polygon.clipped;
            stages.setup(polygon, id, frame, out);
        }
    });
    stats.rasterized = 0;
    for (size_t chunk = 0; chunk < chunks; ++chunk) {
        stats.rasterized += chunk_setups[chunk].size();
        stats.clipped += chunk_clipped[chunk];
    }
}

void concatenate_setups(const std::vector<std::vector<TriangleSetup>>& chunks, int threads,
                        std::vector<TriangleSetup>& out) {
    std::vector<size_t> start(chunks.size() + 1, 0);
    for (size_t chunk = 0; chunk < chunks.size(); ++chunk) start[chunk + 1] = start[chunk] + chunks[chunk].size();
    out.resize(start.back());  // keeps its storage from frame to frame
    parallel_for(chunks.size(), threads, [&](size_t chunk) {
        std::copy(chunks[chunk].begin(), chunks[chunk].end(), out.begin() + static_cast<ptrdiff_t>(start[chunk]));
    });
}

std::vector<TriangleSetup> set_up_triangles(const TransformedScene& geometry, const FrameParams& frame,
                                            const PipelineStages& stages, bool cull_backfaces, RenderStats& stats) {
    RenderWorkspace workspace;
    set_up_triangles_into(geometry, frame, stages, cull_backfaces, stats, workspace);
    std::vector<TriangleSetup> setups;
    concatenate_setups(workspace.setup_chunks, frame.threads, setups);
    return setups;
}

FrontEnd run_front_end(const Scene& scene, const RenderOptions& options, const PipelineStages& stages,
                       RenderResult& result) {
    result.stats = RenderStats{};
    const RenderSettings& settings = scene.settings;
    FrontEnd out{run_vertex_stage_timed(scene, stages, result.stats),
                 frame_params_for(scene, stages.sample_offsets(settings.samples, settings.pattern), options.threads)};
    const auto start = Clock::now();
    set_up_triangles_into(out.geometry, out.frame, stages, settings.cull_backfaces, result.stats, result.workspace);
    split_transparent_setups(transparent_triangles(scene), result.workspace.setup_chunks,
                             result.workspace.transparent_setups);
    result.stats.ms_setup = milliseconds_since(start);
    return out;
}

ShadowMaps build_shadow_maps(const Scene& scene, const FrontEnd& front, const RenderOptions& options,
                             const PipelineStages& stages, RenderStats& stats) {
    if (!has_shadows(scene) || scene.settings.shading == ShadingMode::unlit) return {};
    const auto start = Clock::now();
    ShadowMaps maps(scene, front.geometry.world_position, stages, {options.path, options.allow_simd, options.threads});
    stats.ms_shadow = milliseconds_since(start);
    return maps;
}

void composite_transparency_timed(const Scene& scene, const FrontEnd& front, const Shader& shader,
                                  const ResolveParams& resolve, RenderResult& result) {
    if (result.workspace.transparent_setups.empty()) return;
    const auto start = Clock::now();
    TransparencyInputs inputs;
    inputs.setups = &result.workspace.transparent_setups;
    inputs.frame = &front.frame;
    inputs.opaque = &result.visibility;
    inputs.shader = &shader;
    inputs.resolve = resolve;
    inputs.settings = scene.settings.transparency;
    result.stats.transparent_fragments = composite_transparency(inputs, result.image);
    result.stats.ms_transparency = milliseconds_since(start);
}

ResolveParams resolve_params_for(const Scene& scene, const RenderOptions& options) {
    ResolveParams params;
    params.msaa = scene.settings.msaa;
    params.background = scene.settings.background;
    params.alpha = options.alpha;
    params.threads = options.threads;
    return params;
}

}  // namespace raster
