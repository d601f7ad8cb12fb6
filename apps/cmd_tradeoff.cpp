// `raster tradeoff`: times every speed/accuracy mode on each scene, measures its error against the Embree oracle,
// and writes tradeoff.json, tradeoff.csv and pareto.svg.
#include <cstdio>
#include <filesystem>
#include <memory>

#include "apps/command.h"
#include "apps/settings_flags.h"
#include "apps/progress_bar.h"
#include "oracle/reference/embree_device.h"
#include "harness/tradeoff/pareto_plot.h"
#include "harness/tradeoff/tradeoff.h"
#include "harness/tradeoff/tradeoff_modes.h"
#include "raster/core/errors.h"
#include "raster/core/file_io.h"
#include "raster/frame/render.h"
#include "raster/compat/scene_loader.h"
#include "raster/scene/validation.h"

namespace raster::cli {
namespace {

namespace fs = std::filesystem;

struct TradeoffFlags {
    std::vector<std::string> scenes;
    std::string output_dir = "tradeoff";
    std::vector<std::string> modes;
    int runs = 5;
    int reference_grid = 8;
    bool fast_oracle = false;
    int threads = 0;
    bool list_modes = false;
};

void register_tradeoff_flags(CLI::App& app, TradeoffFlags& flags) {
    CLI::App* tradeoff = app.add_subcommand(
        "tradeoff",
        "Measure each speed/accuracy mode's frame time and error against the oracle, and plot the Pareto front.");
    tradeoff->footer(
        "For every scene and mode: the median time of --runs frames (timed in rounds of one frame per mode, after an\n"
        "untimed warm-up round), the genuine and ambiguous sample counts of `raster compare`, the colour RMSE (0-255,\n"
        "RGB) against the oracle's image at\n"
        "--reference-grid squared samples per pixel, and the coverage error sum_t |n_t/spp - A_t| / sum_t A_t (n_t:\n"
        "samples triangle t's snapped setups cover, A_t: its exact visible area in px^2). The default modes are the\n"
        "scene's own settings (baseline), every one-axis variation that differs from it, and the presets fastest,\n"
        "balanced and exact; --list-modes lists them all. Writes DIR/tradeoff.json, DIR/tradeoff.csv and\n"
        "DIR/pareto.svg (time against colour RMSE, the Pareto front in red). `raster report -o R` links R/tradeoff/.\n"
        "Exit code 0 on success, 2 on bad input (nothing written), 3 when an output cannot be written or Embree "
        "fails.\n"
        "Example: raster tradeoff corpus/scenes/teapot.yaml -o report/tradeoff --modes baseline,samples4,fastest");
    tradeoff->add_option("scenes", flags.scenes, "Scene files");
    tradeoff->add_option("-o,--output", flags.output_dir, "Directory to write the results into (default: tradeoff)");
    tradeoff
        ->add_option("--modes", flags.modes,
                     "Comma-separated mode names to measure (default: the sweep described below)")
        ->delimiter(',');
    tradeoff->add_option("--runs", flags.runs, "Timed frames per mode; the median is reported (default 5)")
        ->check(CLI::Range(1, 100));
    tradeoff
        ->add_option("--reference-grid", flags.reference_grid,
                     "Side N of the reference oracle image's N x N sample grid (default 8: 64 samples per pixel)")
        ->check(CLI::Range(1, 16));
    add_fast_oracle_flag(*tradeoff, flags.fast_oracle);
    tradeoff
        ->add_option("--threads", flags.threads, "Worker threads, 0 = all cores (errors are the same for any count)")
        ->check(CLI::Range(0, 256));
    tradeoff->add_flag("--list-modes", flags.list_modes, "List every mode with what it changes, and exit");
}

// The modes the flags ask for on a scene with `baseline` settings: the named ones (each checked), or the default
// sweep. A mode whose settings the scene cannot render (e.g. too many samples for its size) is an error when named
// and left out with a warning otherwise.
std::vector<const harness::TradeoffMode*> modes_for(const TradeoffFlags& flags, const Scene& scene, std::ostream& err) {
    std::vector<const harness::TradeoffMode*> modes;
    if (flags.modes.empty()) {
        for (const harness::TradeoffMode* mode : harness::default_sweep(scene.settings, harness::scene_features(scene))) {
            const std::string problem = settings_problem(harness::apply_mode(*mode, scene.settings));
            if (problem.empty())
                modes.push_back(mode);
            else
                err << "raster tradeoff: warning: " << scene.path << ": mode " << mode->name << " left out: " << problem
                    << "\n";
        }
        return modes;
    }
    for (const std::string& name : flags.modes) {
        const harness::TradeoffMode* mode = harness::find_tradeoff_mode(name);
        if (!mode)
            throw InputError("", 0, 0, "unknown mode '" + name + "'; the modes are " + harness::tradeoff_mode_names());
        bool repeated = false;
        for (const harness::TradeoffMode* earlier : modes) repeated = repeated || earlier == mode;
        if (repeated) continue;
        const RenderSettings settings = harness::apply_mode(*mode, scene.settings);
        if (std::string problem = settings_problem(settings); !problem.empty())
            throw InputError(scene.path, 0, 0, "mode " + name + ": " + problem);
        if (name != "baseline" && harness::same_mode_settings(settings, scene.settings))
            err << "raster tradeoff: warning: " << scene.path << ": mode " << name
                << " changes nothing on this scene (measured as the baseline is)\n";
        modes.push_back(mode);
    }
    return modes;
}

void print_scene(const harness::SceneTradeoff& scene, int reference_grid, std::ostream& out) {
    char line[512];
    std::snprintf(line, sizeof line, "%s: %dx%d, %zu triangles, %dx%d oracle reference (%.0f ms)\n", scene.name.c_str(),
                  scene.width, scene.height, scene.triangles, reference_grid, reference_grid, scene.reference_ms);
    out << line;
    std::snprintf(line, sizeof line, "  %-18s %10s %10s %10s %8s %10s  %s\n", "mode", "median ms", "genuine",
                  "ambiguous", "RMSE", "coverage", "front");
    out << line;
    for (const harness::ModeResult& m : scene.modes) {
        auto count = [&](uint64_t value) { return m.compared ? std::to_string(value) : std::string("-"); };
        std::snprintf(line, sizeof line, "  %-18s %10.2f %10s %10s %8.3f %10.5f  %s\n", m.mode.c_str(), m.median_ms,
                      count(m.genuine).c_str(), count(m.ambiguous).c_str(), m.color_rmse, m.coverage_error,
                      m.on_front ? "*" : "");
        out << line;
    }
}

int run_tradeoff(const TradeoffFlags& flags, std::ostream& out, std::ostream& err) {
    if (flags.list_modes) {
        for (const harness::TradeoffMode& mode : harness::tradeoff_modes()) {
            char line[256];
            std::snprintf(line, sizeof line, "%-18s %s\n", mode.name.c_str(), mode.description.c_str());
            out << line;
        }
        return kExitOk;
    }
    harness::TradeoffOptions options;
    options.runs = flags.runs;
    options.reference_grid = flags.reference_grid;
    options.oracle_mode = flags.fast_oracle ? oracle::OracleMode::fast : oracle::OracleMode::robust;
    options.threads = flags.threads;

    // Everything is read and checked before anything is rendered or written.
    std::vector<Scene> scenes;
    std::vector<std::vector<const harness::TradeoffMode*>> modes;
    try {
        if (flags.scenes.empty()) throw InputError("", 0, 0, "no scene given (raster tradeoff SCENE... [-o DIR])");
        for (const std::string& file : flags.scenes) {
            Scene scene = load_scene(file);
            if (std::string problem = harness::reference_problem(scene.settings, flags.reference_grid); !problem.empty())
                throw InputError(file, 0, 0, problem);
            modes.push_back(modes_for(flags, scene, err));
            scenes.push_back(std::move(scene));
        }
    } catch (const InputError& error) {
        err << "raster tradeoff: error: " << error.what() << "\n";
        return kExitBadInput;
    }
    if (flags.runs < 5)
        err << "raster tradeoff: warning: " << flags.runs << " timed run" << (flags.runs == 1 ? "" : "s")
            << " per mode; medians of fewer than 5 are noisy\n";

    const fs::path dir = flags.output_dir;
    std::error_code dir_error;
    fs::create_directories(dir, dir_error);
    if (dir_error) {
        err << "raster tradeoff: error: cannot create " << dir << ": " << dir_error.message() << "\n";
        return kExitIoError;
    }
    size_t steps = 0;
    for (const auto& scene_modes : modes) steps += harness::measure_steps(scene_modes.size(), options);
    ProgressBar progress(err, steps);
    size_t done = 0;
    std::vector<harness::SceneTradeoff> results;
    try {
        for (size_t i = 0; i < scenes.size(); ++i) {
            results.push_back(harness::measure_scene(scenes[i], modes[i], options,
                                                    [&](const std::string& label) { progress.show(done++, label); }));
            progress.finish();
            print_scene(results.back(), flags.reference_grid, out);
            for (const harness::ModeResult& m : results.back().modes)
                if (!m.timed_image_matches)
                    err << "raster tradeoff: warning: " << scenes[i].path << ": mode " << m.mode
                        << ": the timed frame's image differs from the one compared with the oracle\n";
            out << std::flush;
        }
        progress.show(steps, "done");
        progress.finish();
        write_file_atomically(dir / "tradeoff.json", harness::tradeoff_json(results, options).dump(2) + "\n");
        write_file_atomically(dir / "tradeoff.csv", harness::tradeoff_csv(results));
        write_file_atomically(dir / "pareto.svg", harness::pareto_svg(results, flags.reference_grid));
    } catch (const std::exception& error) {
        progress.finish();
        err << "raster tradeoff: error: " << error.what() << "\n";
        return kExitIoError;
    }
    out << "tradeoff: " << (dir / "tradeoff.json").string() << ", " << (dir / "tradeoff.csv").string() << ", "
        << (dir / "pareto.svg").string() << "\n";
    return kExitOk;
}

}  // namespace

Command add_tradeoff_command(CLI::App& app) {
    return flags_command<TradeoffFlags>(app, "tradeoff", register_tradeoff_flags, run_tradeoff);
}

}  // namespace raster::cli
