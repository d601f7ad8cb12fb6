// `raster render`: renders a scene file to an image, with flags that override the scene's settings.
#include <filesystem>
#include <memory>
#include <optional>
#include <vector>

#include <nlohmann/json.hpp>

#include "apps/backends.h"
#include "backends/plugin/plugin_error.h"
#include "apps/command.h"
#include "apps/render_outputs.h"
#include "apps/settings_flags.h"
#include "harness/tradeoff/tradeoff.h"
#include "raster/core/errors.h"
#include "raster/image/image.h"
#include "raster/frame/render_job.h"
#include "raster/core/parallel.h"
#include "raster/core/stopwatch.h"
#include "raster/compat/scene_loader.h"

namespace raster::cli {
namespace {

// Flags of `raster render`; the settings flags override the scene's own settings when given.
struct RenderFlags {
    std::string scene;
    std::string output;
    SettingsFlags settings;
    std::string depth_out;
    bool stats = false;
    int repeat = 1;  // frames rendered, each reusing the previous one's buffers; the last is written
    std::string backend = "raster";
};

void register_render_flags(CLI::App& app, RenderFlags& flags) {
    CLI::App* render = app.add_subcommand("render", "Render a scene to a PNG or PPM image.");
    render->footer(
        "SCENE is a raster YAML scene, a seed 000 YAML config (its task decides the output), a seed 001 balboa JSON\n"
        "scene or a seed 003 JSON scene, told apart by content (see docs/scene-format.md); or a glTF 2.0 file\n"
        "(.gltf, .glb; docs/gltf.md) or an OBJ or PLY mesh alone, framed by a default camera and light.\n"
        "Flags override the scene's settings. Example: raster render corpus/scenes/teapot.yaml -o teapot.png --samples 4");
    render->add_option("scene", flags.scene, "Scene file")->required();
    render->add_option("-o,--output", flags.output,
                       "Output image; .ppm writes binary PPM, anything else PNG (default: SCENE's stem + .png in the "
                       "current directory)");
    register_settings_flags(*render, flags.settings);
    render->add_option("--depth-out", flags.depth_out,
                       "Also write a greyscale depth image (nearest white, farthest dark grey, empty black)");
    render->add_flag("--stats", flags.stats,
                     "Print one JSON line of counts and in-process timings (loading excluded) on stdout");
    render->add_option("--repeat", flags.repeat,
                       "Render the frame N times, each reusing the previous frame's buffers (1..10000, default 1); "
                       "--stats then adds ms_first and ms_median of the frames' ms_total")
        ->check(CLI::Range(1, 10000));
    render->add_option("--backend", flags.backend,
                       "What draws the frame: raster (the default); gl, OpenGL 4.5 through Mesa's EGL with GLSL of "
                       "our own (unlit, phong and blinn-phong, 1 or 4 samples, untextured and opaque: docs/gl.md); or "
                       "plugin:PATH, your own rasterizer as a shared library (docs/plugins.md)")
        ->check(backend_name_validator());
}

nlohmann::json stats_json(const Scene& scene, const RenderStats& stats) {
    return {{"scene", scene.path},
            {"width", scene.settings.width},
            {"height", scene.settings.height},
            {"samples_per_pixel", scene.settings.samples},
            {"shading", to_string(scene.settings.shading)},
            {"snap_bits", scene.settings.snap_bits},
            {"edges", to_string(scene.settings.modes.edges)},
            {"interpolation", to_string(scene.settings.modes.interpolation)},
            {"depth_format", to_string(scene.settings.modes.depth)},
            {"clipping", to_string(scene.settings.modes.clipping)},
            {"hierarchical_z", scene.settings.modes.hierarchical_z},
            {"resolution_divisor", scene.settings.resolution_divisor},
            {"triangles", stats.triangles},
            {"clipped", stats.clipped},
            {"rasterized", stats.rasterized},
            {"samples", stats.samples},
            {"covered_samples", stats.covered_samples},
            {"hidden_blocks", stats.hidden_blocks},
            {"transparent_fragments", stats.transparent_fragments},
            {"ms_vertex", stats.ms_vertex},
            {"ms_setup", stats.ms_setup},
            {"ms_shadow", stats.ms_shadow},
            {"ms_raster", stats.ms_raster},
            {"ms_shade", stats.ms_shade},
            {"ms_transparency", stats.ms_transparency},
            {"ms_upscale", stats.ms_upscale},
            {"ms_total", stats.ms_total}};
}

int run_render(const RenderFlags& flags, std::ostream& out, std::ostream& err) {
    SceneFile file;
    const auto load_start = Clock::now();
    try {
        start_threads(flags.settings.threads);  // the workers start while the scene loads
        file = load_scene_file(flags.scene, load_options(flags.settings));
        apply_settings_flags(flags.settings, file.scene);
    } catch (const InputError& error) {
        err << "raster render: error: " << error.what() << "\n";
        return kExitBadInput;
    }
    const Scene& scene = file.scene;
    const double ms_load = milliseconds_since(load_start);
    if (file.request.self_check) return file.request.self_check(out) ? kExitOk : kExitCheckFailed;
    RenderJob job = render_job_for(flags.scene, file.request, flags.output, flags.depth_out);
    job.options.threads = flags.settings.threads;
    job.options.alpha = flags.settings.alpha;
    job.repeat = flags.repeat;
    RenderedFrame rendered;
    try {
        const std::unique_ptr<Renderer> renderer = renderer_named(flags.backend);
        run_render_job(scene, job, *renderer, rendered);
    } catch (const InputError& error) {  // what the backend cannot draw
        err << "raster render: error: " << flags.scene << ": " << error.what() << "\n";
        return kExitBadInput;
    } catch (const OutputError& error) {
        err << "raster render: error: " << error.what() << "\n";
        return kExitIoError;
    } catch (const plugin::PluginError& error) {  // the rasterizer under test failed
        err << "raster render: " << flags.scene << ": " << error.what() << "\n";
        return kExitCheckFailed;
    } catch (const std::runtime_error& error) {  // no OpenGL context
        err << "raster render: error: " << error.what() << "\n";
        return kExitIoError;
    }
    const RenderResult& result = rendered.result;
    const std::vector<double>& frame_ms = rendered.frame_ms;
    const double ms_write = rendered.ms_write;
    if (flags.stats) {
        nlohmann::json stats = stats_json(scene, result.stats);
        stats["ms_load"] = ms_load;    // reading and checking the scene and its files
        stats["ms_write"] = ms_write;  // encoding and writing the image(s)
        if (flags.repeat > 1) {
            stats["frames"] = flags.repeat;
            stats["ms_first"] = frame_ms.front();
            stats["ms_median"] = harness::median(frame_ms);
        }
        out << stats.dump() << "\n";
    }
    return kExitOk;
}

}  // namespace

Command add_render_command(CLI::App& app) {
    return flags_command<RenderFlags>(app, "render", register_render_flags, run_render);
}

}  // namespace raster::cli
