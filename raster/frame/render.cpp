// The frame's order: front end, shadow pass, the backend's opaque raster and resolve, transparency; each timed;
// and a reduced-resolution frame's upscale.
#include "raster/frame/render.h"

#include <stdexcept>
#include <string>
#include <utility>

#include "raster/core/stopwatch.h"
#include "raster/geometry/front_end.h"
#include "raster/frame/reference_renderer.h"
#include "raster/resolve/resolve.h"
#include "raster/shading/shade.h"
#include "raster/frame/shadow_pass.h"
#include "raster/frame/tiled_renderer.h"
#include "raster/resolve/transparency.h"
#include "raster/resolve/upscale.h"
#include "raster/geometry/vertex_stage.h"

namespace raster {
namespace {

ResolveParams resolve_params_for(const Scene& scene, const RenderOptions& options) {
    ResolveParams params;
    params.msaa = scene.settings.msaa;
    params.background = scene.settings.background;
    params.alpha = options.alpha;
    return params;
}

// The frame at the scene's own size: every stage, timed into result.stats.
void render_native(const Scene& scene, const RenderOptions& options, const RasterBackend& backend,
                   RenderResult& result) {
    const auto start = Clock::now();
    const RenderSettings& settings = scene.settings;
    RenderStats& stats = result.stats = RenderStats{};

    // Front end: the vertex stage for what the shading needs, then cull, clip and set up, the transparent
    // triangles' setups set aside.
    auto stage_start = Clock::now();
    const TransformedScene geometry = run_vertex_stage(scene, vertex_stage_needs(settings.shading));
    stats.triangles = geometry.triangles.size();
    stats.ms_vertex = milliseconds_since(stage_start);
    const FrameParams frame =
        frame_params_for(scene, sample_offsets(settings.samples, settings.pattern), options.threads);
    stage_start = Clock::now();
    FrontEndSetups& front_end = result.workspace.front_end;
    const SetupCounts counts =
        set_up_triangles_into(geometry, frame, settings.cull_backfaces, transparent_triangles(scene), front_end);
    stats.clipped = counts.clipped;
    stats.rasterized = counts.rasterized;
    stats.ms_setup = milliseconds_since(stage_start);

    // Shadow pass: the maps the frame needs, none unless a light casts shadows and the shading is lit.
    ShadowMaps shadows;
    if (has_shadows(scene) && settings.shading != ShadingMode::unlit) {
        stage_start = Clock::now();
        shadows = render_shadow_maps(scene, geometry.world_position, backend, options.threads);
        stats.ms_shadow = milliseconds_since(stage_start);
    }

    // Opaque raster and resolve: the backend draws the opaque setups and shades and resolves their pixels (the
    // tiled backend interleaves the two tile by tile). The transparency pass reads the opaque samples.
    const Shader shader(scene, geometry, &shadows);
    const ResolveParams resolve = resolve_params_for(scene, options);
    const PixelResolver resolver(shader, resolve, frame.samples());
    const bool transparent = !front_end.transparent_setups.empty();
    const OpaqueDrawStats drawn =
        backend.draw_opaque({frame, resolver, options.keep_visibility || transparent, &geometry}, result);
    stats.ms_setup += drawn.ms_bin;
    stats.ms_raster = drawn.ms_raster;
    stats.ms_shade = drawn.ms_shade;
    stats.samples = static_cast<size_t>(frame.width) * frame.height * frame.samples();
    stats.covered_samples = drawn.covered_samples;
    stats.hidden_blocks = drawn.hidden_blocks;

    // Transparency: the transparent setups blended over the resolved opaque frame.
    if (transparent) {
        stage_start = Clock::now();
        TransparencyInputs inputs;
        inputs.setups = &front_end.transparent_setups;
        inputs.frame = &frame;
        inputs.opaque = &result.visibility;
        inputs.shader = &shader;
        inputs.resolve = resolve;
        inputs.settings = settings.transparency;
        stats.transparent_fragments = composite_transparency(inputs, result.image);
        stats.ms_transparency = milliseconds_since(stage_start);
    }
    stats.ms_total = milliseconds_since(start);
}

}  // namespace

const RasterBackend& raster_backend(RasterPath path, bool allow_simd) {
    static const TiledBackend simd(true), scalar(false);
    static const ReferenceBackend reference;
    if (path == RasterPath::reference) return reference;
    return allow_simd ? static_cast<const RasterBackend&>(simd) : scalar;
}

void render_frame(const Scene& scene, const RenderOptions& options, const RasterBackend& backend,
                  RenderResult& result) {
    const int divisor = scene.settings.resolution_divisor;
    if (divisor == 1) return render_native(scene, options, backend, result);
    if (!valid_resolution_divisor(divisor) || scene.settings.width % divisor != 0 || scene.settings.height % divisor != 0)
        throw std::invalid_argument("render_frame: resolution divisor " + std::to_string(divisor) +
                                    " is not 2 or 4 dividing the image size (validate the scene first)");
    // Reduced resolution: the whole frame at width/d x height/d (its visibility buffer stays at that size), then
    // its image stretched to the output size.
    const auto start = Clock::now();
    Scene internal = scene;
    internal.settings = internal_frame_settings(scene.settings);
    render_native(internal, options, backend, result);
    const auto upscale_start = Clock::now();
    RenderWorkspace& workspace = result.workspace;
    std::swap(result.image, workspace.internal_image);
    upscale_image(workspace.internal_image, divisor, options.threads, workspace.upscale_rows, result.image);
    result.stats.ms_upscale = milliseconds_since(upscale_start);
    result.stats.ms_total = milliseconds_since(start);
}

RenderResult render(const Scene& scene, const RenderOptions& options) {
    RenderResult result;
    render_into(scene, options, result);
    return result;
}

void render_into(const Scene& scene, const RenderOptions& options, RenderResult& result) {
    render_frame(scene, options, raster_backend(options.path, options.allow_simd), result);
}

}  // namespace raster
