// `raster compare`: renders a scene as `raster render` does and with the independent oracle, classes every sample
// and checks every pixel of the image raster writes.
#include <filesystem>
#include <memory>

#include <nlohmann/json.hpp>

#include "apps/backends.h"
#include "backends/plugin/plugin_library.h"
#include "apps/command.h"
#include "apps/render_outputs.h"
#include "apps/settings_flags.h"
#include "harness/comparison/comparison_output.h"
#include "harness/comparison/junit_report.h"
#include "oracle/compare/diff_map.h"
#include "oracle/reference/embree_device.h"
#include "raster/core/errors.h"
#include "raster/core/file_io.h"
#include "raster/image/image.h"
#include "raster/compat/scene_loader.h"

namespace raster::cli {
namespace {

struct CompareFlags {
    std::string scene;
    SettingsFlags settings;
    std::string json_out;
    std::string diff_out;
    std::string junit_out;
    bool fast_oracle = false;
    std::string backend = "raster";
};

void register_compare_flags(CLI::App& app, CompareFlags& flags) {
    CLI::App* compare = app.add_subcommand(
        "compare", "Render a scene as `raster render` does and with the independent Embree oracle, and class every "
                   "sample's and every pixel's disagreement.");
    compare->footer(
        "The scene is rendered once, by the same job `raster render` runs, into a temporary folder: its image as PNG\n"
        "and as PPM, and its depth image. Every sample is classed as agree, ambiguous (edge band, depth tie, clip\n"
        "boundary, facing: allowed by the precision model) or genuine (visibility, barycentrics, depth); every pixel\n"
        "whose samples all agree has its colour, as read back from each file, checked against the oracle's bounds\n"
        "(genuine: colour), and every pixel of the depth files against the depth image's definition over raster's\n"
        "samples (genuine: depth image). A seed 000 shading-depth config writes its depth image only.\n"
        "Precision modes beyond the oracle's bounds leave classes unjudged (counted, not failed): visibility under\n"
        "--edges float, --clipping guard-band and --depth-format float|fixed24; barycentrics, depth and colour\n"
        "under --interpolation affine. The summary, the JSON (\"unjudged\") and the report name them.\n"
        "The settings flags are render's. Exit code 0 when genuine_total is 0, 1 when not, 2 on bad input, 3 when an\n"
        "output cannot be written or Embree fails.\n"
        "Example: raster compare corpus/scenes/teapot.yaml --samples 16 --json teapot.json --diff teapot-diff.png");
    compare->add_option("scene", flags.scene, "Scene file")->required();
    register_settings_flags(*compare, flags.settings);
    compare->add_option("--json", flags.json_out, "Write the counts and timings as JSON to this file");
    compare->add_option("--junit", flags.junit_out,
                        "Write the verdict as JUnit XML to this file (one test case, failed when genuine_total > 0), "
                        "for CI systems");
    compare->add_option("--diff", flags.diff_out,
                        "Write a disagreement map: genuine samples red, genuine colour magenta, ambiguous yellow, "
                        "agreeing dimmed grey");
    add_fast_oracle_flag(*compare, flags.fast_oracle);
    compare->add_option("--backend", flags.backend,
                        "What renders the frame the oracle judges, sample by sample: raster (the default); gl, "
                        "OpenGL on Mesa's EGL (docs/gl.md); or plugin:PATH, your own rasterizer as a shared library "
                        "(docs/plugins.md)")
        ->check(backend_name_validator());
}

int run_compare(const CompareFlags& flags, std::ostream& out, std::ostream& err) {
    SceneFile file;
    Scene& scene = file.scene;
    try {
        file = load_scene_with_flags(flags.scene, flags.settings);
        if (file.request.self_check)
            throw InputError(flags.scene, 0, 0,
                             "this file asks for a check of its own, not an image: `raster render` writes nothing to "
                             "compare (run it with `raster render`)");
        if (std::string problem = harness::comparison_problem(scene); !problem.empty())
            throw InputError(flags.scene, 0, 0, problem);
    } catch (const InputError& error) {
        err << "raster compare: error: " << error.what() << "\n";
        return kExitBadInput;
    }
    harness::ComparisonOptions options;
    options.mode = flags.fast_oracle ? oracle::OracleMode::fast : oracle::OracleMode::robust;
    options.threads = flags.settings.threads;
    options.alpha = flags.settings.alpha;
    // What `raster render` writes for this file: its colour image unless the file asks for the depth image; and the
    // depth image, which the file or --depth-out can ask for.
    options.colour_output = image_kind_for(file.request) == OutputKind::colour;
    options.depth_output = true;
    std::unique_ptr<harness::Comparison> comparison;
    try {
        const std::unique_ptr<Renderer> renderer = renderer_named(flags.backend);
        options.renderer = renderer.get();
        comparison = std::make_unique<harness::Comparison>(harness::compare_scene(scene, options));
    } catch (const InputError& error) {  // what the backend cannot draw
        err << "raster compare: error: " << flags.scene << ": " << error.what() << "\n";
        return kExitBadInput;
    } catch (const OutputError& error) {
        err << "raster compare: error: " << error.what() << "\n";
        return kExitIoError;
    } catch (const plugin::PluginError& error) {  // the rasterizer under test failed: a finding
        err << "raster compare: " << flags.scene << ": " << error.what() << "\n";
        return kExitCheckFailed;
    } catch (const oracle::OracleError& error) {
        err << "raster compare: error: " << error.what() << "\n";
        return kExitIoError;
    } catch (const std::runtime_error& error) {  // no OpenGL context
        err << "raster compare: error: " << error.what() << "\n";
        return kExitIoError;
    }
    try {
        if (!flags.json_out.empty())
            write_file_atomically(flags.json_out, harness::comparison_json(*comparison).dump(2) + "\n");
        if (!flags.diff_out.empty()) write_image(flags.diff_out, harness::diff_map(*comparison), options.threads);
        if (!flags.junit_out.empty())
            write_file_atomically(flags.junit_out,
                                  harness::junit_xml("raster compare", {harness::junit_case(*comparison, flags.scene)},
                                                     harness::junit_timestamp_now(), harness::junit_hostname()));
    } catch (const std::exception& error) {
        err << "raster compare: error: " << error.what() << "\n";
        return kExitIoError;
    }
    out << harness::comparison_summary(*comparison);
    return comparison->genuine_total() == 0 ? kExitOk : kExitCheckFailed;
}

}  // namespace

Command add_compare_command(CLI::App& app) {
    return flags_command<CompareFlags>(app, "compare", register_compare_flags, run_compare);
}

}  // namespace raster::cli
