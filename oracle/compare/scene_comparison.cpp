// A comparison run: raster, oracle, reference geometry and comparator in order, each timed.
#include "oracle/compare/scene_comparison.h"

#include <chrono>
#include <cstdio>
#include <memory>

#include "oracle/reference/reference_geometry.h"
#include "raster/pipeline/camera_rays.h"
#include "raster/pipeline/resolve.h"
#include "raster/pipeline/sample_pattern.h"
#include "raster/pipeline/shade.h"
#include "raster/pipeline/vertex_stage.h"
#include "raster/core/stopwatch.h"

namespace raster::oracle {
namespace {


// The real vertex stage (one overload of run_vertex_stage), to tell whether `stages` replaced it.
constexpr TransformedScene (*kRealVertexStage)(const Scene&, const VertexStageNeeds&) = run_vertex_stage;

}  // namespace

Comparison compare_scene(const Scene& scene, const ComparisonOptions& options, const PipelineStages& stages) {
    Comparison out;
    out.scene = scene.path;
    out.width = scene.settings.width;
    out.height = scene.settings.height;
    out.samples = scene.settings.samples;
    out.mode = options.mode;

    RenderOptions render_options;
    render_options.threads = options.threads;
    render_options.path = options.raster_path;
    out.raster = render(scene, render_options, stages);
    out.raster_ms = out.raster.stats.ms_total;

    auto start = Clock::now();
    const VertexStageNeeds needs = vertex_stage_needs(scene.settings.shading);
    const TransformedScene geometry = run_vertex_stage(scene, needs);
    OracleOptions oracle_options;
    oracle_options.mode = options.mode;
    oracle_options.threads = options.threads;
    render_oracle(scene, geometry, oracle_options, out.oracle_visibility);
    const Shader reference_shader(scene, geometry);
    ResolveParams resolve_params;
    resolve_params.msaa = scene.settings.msaa;
    resolve_params.background = scene.settings.background;
    resolve_params.threads = options.threads;
    resolve_image(out.oracle_visibility, reference_shader, resolve_params, out.oracle_image);
    out.oracle_ms = milliseconds_since(start);

    start = Clock::now();
    // raster's own shading, when its pipeline changed what shading reads (the vertex stage or the lighting).
    std::unique_ptr<TransformedScene> raster_geometry;
    std::unique_ptr<Shader> raster_shader;
    if (stages.vertex != kRealVertexStage || stages.lighting != evaluate_lighting) {
        raster_geometry = std::make_unique<TransformedScene>(stages.vertex(scene, needs));
        raster_shader = std::make_unique<Shader>(scene, *raster_geometry, stages.lighting);
    }
    const ReferenceGeometry reference(scene, geometry);
    CompareInputs inputs;
    inputs.raster = &out.raster.visibility;
    inputs.oracle = &out.oracle_visibility;
    inputs.reference = &reference;
    inputs.reference_shader = &reference_shader;
    inputs.raster_shader = raster_shader ? raster_shader.get() : &reference_shader;
    inputs.fixed_bits = fixed_bits_for(scene.settings.snap_bits);
    inputs.offsets = fixed_sample_offsets(sample_offsets(scene.settings.samples, scene.settings.pattern), inputs.fixed_bits);
    inputs.threads = options.threads;
    VisibilityComparison comparison = compare_visibility(inputs);
    out.counts = comparison.counts;
    out.max_color_error = comparison.max_color_error;
    out.classes = std::move(comparison.classes);
    out.compare_ms = milliseconds_since(start);
    return out;
}

nlohmann::json comparison_json(const Comparison& c) {
    auto count = [&](SampleClass k) { return c.counts.count(k); };
    return {{"scene", c.scene},
            {"width", c.width},
            {"height", c.height},
            {"samples", c.samples},
            {"oracle_mode", to_string(c.mode)},
            {"agree", count(SampleClass::agree)},
            {"ambiguous",
             {{"edge_band", count(SampleClass::edge_band)},
              {"depth_tie", count(SampleClass::depth_tie)},
              {"clip_boundary", count(SampleClass::clip_boundary)},
              {"facing", count(SampleClass::facing)}}},
            {"ambiguous_total", c.counts.ambiguous_total()},
            {"genuine",
             {{"visibility", count(SampleClass::visibility)},
              {"barycentrics", count(SampleClass::barycentrics)},
              {"depth", count(SampleClass::depth)},
              {"color", count(SampleClass::color)}}},
            {"genuine_total", c.counts.genuine_total()},
            {"max_color_error", c.max_color_error},
            {"raster_ms", c.raster_ms},
            {"oracle_ms", c.oracle_ms},
            {"compare_ms", c.compare_ms}};
}

std::string comparison_summary(const Comparison& c) {
    auto count = [&](SampleClass k) { return static_cast<unsigned long long>(c.counts.count(k)); };
    char text[1024];
    std::snprintf(text, sizeof text,
                  "%s: %dx%d, %d samples per pixel, oracle %s\n"
                  "  agree      %llu\n"
                  "  ambiguous  %llu (edge band %llu, depth tie %llu, clip boundary %llu, facing %llu)\n"
                  "  genuine    %llu (visibility %llu, barycentrics %llu, depth %llu, colour %llu)\n"
                  "  max colour error %d/255 on agreeing samples\n"
                  "  raster %.1f ms, oracle %.1f ms, compare %.1f ms\n",
                  c.scene.c_str(), c.width, c.height, c.samples, to_string(c.mode), count(SampleClass::agree),
                  static_cast<unsigned long long>(c.counts.ambiguous_total()), count(SampleClass::edge_band),
                  count(SampleClass::depth_tie), count(SampleClass::clip_boundary), count(SampleClass::facing),
                  static_cast<unsigned long long>(c.counts.genuine_total()), count(SampleClass::visibility),
                  count(SampleClass::barycentrics), count(SampleClass::depth), count(SampleClass::color),
                  c.max_color_error, c.raster_ms, c.oracle_ms, c.compare_ms);
    return text;
}

}  // namespace raster::oracle
