// `raster compare`: renders a scene with raster and with the Embree oracle and classes every sample.
#include <filesystem>
#include <memory>
#include <optional>

#include <nlohmann/json.hpp>

#include "apps/command.h"
#include "oracle/compare/scene_comparison.h"
#include "oracle/compare/diff_map.h"
#include "oracle/reference/embree_device.h"
#include "raster/core/errors.h"
#include "raster/core/file_io.h"
#include "raster/image/image.h"
#include "raster/formats/scene_loader.h"
#include "raster/scene/validation.h"

namespace raster::cli {
namespace {

struct CompareFlags {
    std::string scene;
    std::optional<int> samples;
    std::string json_out;
    std::string diff_out;
    bool fast_oracle = false;
    int threads = 0;
};

void register_compare_flags(CLI::App& app, CompareFlags& flags) {
    CLI::App* compare = app.add_subcommand(
        "compare", "Render a scene with raster and with the Embree oracle, and class every sample's disagreement.");
    compare->footer(
        "Every sample is classed as agree, ambiguous (edge band, depth tie, clip boundary: allowed by the precision\n"
        "model) or genuine (visibility, barycentrics, depth, colour). Exit code 0 when genuine_total is 0, 1 when not,\n"
        "2 on bad input, 3 when an output cannot be written or Embree fails.\n"
        "Example: raster compare corpus/scenes/teapot.yaml --samples 16 --json teapot.json --diff teapot-diff.png");
    compare->add_option("scene", flags.scene, "Scene file")->required();
    compare->add_option("--samples", flags.samples, "Samples per pixel (overrides the scene): 1, 2, 4, 8, 16 or N*N");
    compare->add_option("--json", flags.json_out, "Write the counts and timings as JSON to this file");
    compare->add_option("--diff", flags.diff_out,
                        "Write a disagreement map: genuine red, ambiguous yellow, agreeing dimmed grey");
    compare->add_flag("--fast-oracle", flags.fast_oracle,
                      "Embree without RTC_SCENE_FLAG_ROBUST (faster, less careful; verdicts need the default)");
    compare->add_option("--threads", flags.threads, "Worker threads, 0 = all cores (results are the same for any count)")
        ->check(CLI::Range(0, 256));
}

int run_compare(const CompareFlags& flags, std::ostream& out, std::ostream& err) {
    Scene scene;
    try {
        scene = load_scene(flags.scene);
        if (flags.samples) scene.settings.samples = *flags.samples;
        if (std::string problem = settings_problem(scene.settings); !problem.empty())
            throw InputError(flags.scene, 0, 0, problem);
    } catch (const InputError& error) {
        err << "raster compare: error: " << error.what() << "\n";
        return kExitBadInput;
    }
    oracle::ComparisonOptions options;
    options.mode = flags.fast_oracle ? oracle::OracleMode::fast : oracle::OracleMode::robust;
    options.threads = flags.threads;
    std::unique_ptr<oracle::Comparison> comparison;
    try {
        comparison = std::make_unique<oracle::Comparison>(oracle::compare_scene(scene, options));
    } catch (const oracle::OracleError& error) {
        err << "raster compare: error: " << error.what() << "\n";
        return kExitIoError;
    }
    try {
        if (!flags.json_out.empty())
            write_file_atomically(flags.json_out, oracle::comparison_json(*comparison).dump(2) + "\n");
        if (!flags.diff_out.empty())
            write_image(flags.diff_out,
                        oracle::diff_map(comparison->classes, comparison->samples, comparison->raster.image));
    } catch (const std::exception& error) {
        err << "raster compare: error: " << error.what() << "\n";
        return kExitIoError;
    }
    out << oracle::comparison_summary(*comparison);
    return comparison->counts.genuine_total() == 0 ? kExitOk : kExitCheckFailed;
}

}  // namespace

Command add_compare_command(CLI::App& app) {
    auto flags = std::make_shared<CompareFlags>();
    register_compare_flags(app, *flags);
    return {app.get_subcommand("compare"),
            [flags](std::ostream& out, std::ostream& err) { return run_compare(*flags, out, err); }};
}

}  // namespace raster::cli
