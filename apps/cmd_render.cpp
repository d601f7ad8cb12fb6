// `raster render`: renders a scene file to an image, with flags that override the scene's settings.
#include <filesystem>
#include <memory>
#include <optional>
#include <vector>

#include <nlohmann/json.hpp>

#include "apps/command.h"
#include "apps/settings_flags.h"
#include "harness/tradeoff/tradeoff.h"
#include "raster/core/errors.h"
#include "raster/image/image.h"
#include "raster/frame/render.h"
#include "raster/resolve/depth_image.h"
#include "raster/formats/scene_format_seed000.h"
#include "raster/core/parallel.h"
#include "raster/core/stopwatch.h"
#include "raster/formats/scene_loader.h"

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
};

void register_render_flags(CLI::App& app, RenderFlags& flags) {
    CLI::App* render = app.add_subcommand("render", "Render a scene to a PNG or PPM image.");
    render->footer(
        "SCENE is a raster YAML scene, a seed 000 YAML config (its task decides the output), a seed 001 balboa JSON\n"
        "scene or a seed 003 JSON scene, told apart by content (see README).\n"
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
            {"ms_total", stats.ms_total}};
}

int run_render(const RenderFlags& flags, std::ostream& out, std::ostream& err) {
    Scene scene;
    std::optional<Seed000Config> seed000;  // a seed 000 config's task decides what is written
    const auto load_start = Clock::now();
    try {
        SceneFormat format = SceneFormat::raster;
        start_threads(flags.settings.threads);  // the workers start while the scene loads
        scene = load_scene(flags.scene, &format);
        if (format == SceneFormat::seed000) seed000 = load_seed000_config(flags.scene);
        apply_settings_flags(flags.settings, scene);
    } catch (const InputError& error) {
        err << "raster render: error: " << error.what() << "\n";
        return kExitBadInput;
    }
    const double ms_load = milliseconds_since(load_start);
    if (seed000 && seed000->task == Seed000Task::transform_test) {
        const Seed000TestResult test = run_seed000_transform_test(*seed000);
        out << format_seed000_test_result(test);
        return test.match ? kExitOk : kExitCheckFailed;
    }
    std::filesystem::path output = flags.output;
    if (output.empty() && seed000) output = seed000->output;
    if (output.empty()) output = std::filesystem::path(flags.scene).stem().string() + ".png";
    const bool depth_task = seed000 && seed000->task == Seed000Task::shading_depth;
    RenderOptions options;
    options.threads = flags.settings.threads;
    options.alpha = flags.settings.alpha;
    options.keep_visibility = depth_task || !flags.depth_out.empty();  // the full-frame sample planes, only if read
    RenderResult result;
    std::vector<double> frame_ms;
    for (int frame = 0; frame < flags.repeat; ++frame) {
        render_into(scene, options, result);
        frame_ms.push_back(result.stats.ms_total);
    }
    const auto write_start = Clock::now();
    try {
        write_image(output, depth_task ? depth_image(result.visibility) : result.image, options.threads);
        if (!flags.depth_out.empty()) write_image(flags.depth_out, depth_image(result.visibility), options.threads);
    } catch (const std::exception& error) {
        err << "raster render: error: " << error.what() << "\n";
        return kExitIoError;
    }
    const double ms_write = milliseconds_since(write_start);
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
    auto flags = std::make_shared<RenderFlags>();
    register_render_flags(app, *flags);
    return {app.get_subcommand("render"),
            [flags](std::ostream& out, std::ostream& err) { return run_render(*flags, out, err); },
            [flags] { *flags = RenderFlags{}; }};
}

}  // namespace raster::cli
