// The oracle's side of a check (oracle_run.h).
#include "harness/comparison/oracle_run.h"

#include "oracle/compare/layer_check.h"

namespace raster::harness {

OracleRun run_oracle(const Scene& scene, const OracleRunOptions& options, oracle::SampleBuffer& visibility) {
    OracleRun run;
    run.geometry = oracle::oracle_scene(scene);
    oracle::OracleOptions oracle_options;
    oracle_options.mode = options.mode;
    oracle_options.threads = options.threads;
    oracle::render_oracle(scene, run.geometry, oracle_options, visibility);
    if (has_shadows(scene) && scene.settings.shading != ShadingMode::unlit)
        run.shadows = std::make_unique<oracle::ShadowOracle>(scene, run.geometry, options.threads);
    run.shader =
        std::make_unique<oracle::OracleShader>(scene, run.geometry, run.shadows.get(), oracle::ShadowAnswer::exact);
    run.resolve = {scene.settings.samples, scene.settings.msaa, options.alpha, glm::dvec3(scene.settings.background)};
    run.layers = oracle::trace_layers(scene, run.geometry, oracle_options);
    run.transparent = !run.layers.first.empty();
    run.image = oracle::render_image(*run.shader, visibility, run.resolve, options.threads,
                                     run.transparent ? &run.layers : nullptr, scene.settings.transparency.mode);
    return run;
}

oracle::PixelBounds colour_bounds(const Scene& scene, const OracleRun& run, const oracle::ReferenceGeometry& reference,
                                  const std::vector<glm::dvec2>& offsets, const oracle::SampleBuffer& visibility,
                                  const std::vector<oracle::SampleClass>& classes, int threads) {
    oracle::ColourInputs colour;
    colour.oracle = &visibility;
    colour.classes = &classes;
    colour.reference = &reference;
    const oracle::OracleShader allowed(scene, run.geometry, run.shadows.get(), oracle::ShadowAnswer::allowed);
    std::unique_ptr<oracle::OracleShader> open;
    if (run.shadows)
        open = std::make_unique<oracle::OracleShader>(scene, run.geometry, run.shadows.get(), oracle::ShadowAnswer::open);
    colour.shader = &allowed;
    colour.open_shader = open.get();
    colour.resolve = run.resolve;
    colour.offsets = offsets;
    colour.threads = threads;
    oracle::LayerVerdicts layer_verdicts;
    if (run.transparent) {
        oracle::LayerCheckInputs layer_inputs;
        layer_inputs.scene = &scene;
        layer_inputs.layers = &run.layers;
        layer_inputs.oracle = &visibility;
        layer_inputs.reference = &reference;
        for (uint32_t id = 0; id < run.geometry.triangles.size(); ++id)  // culled ones too: their facing may be uncertain
            if (oracle::layered_material(oracle::triangle_material(scene, run.geometry.triangles[id])))
                layer_inputs.transparent.push_back(id);
        layer_inputs.offsets = offsets;
        layer_inputs.threads = threads;
        layer_verdicts = oracle::check_layers(layer_inputs);
        colour.layers = &run.layers;
        colour.layer_verdicts = &layer_verdicts;
        colour.transparency = scene.settings.transparency.mode;
    }
    return oracle::pixel_bounds(colour);
}

}  // namespace raster::harness
