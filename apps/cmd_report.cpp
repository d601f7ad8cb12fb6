// `raster report`: compares many scenes with the oracle and writes index.html, summary.json and the images.
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <set>

#include "apps/command.h"
#include "oracle/comparison.h"
#include "oracle/diff_map.h"
#include "oracle/embree_device.h"
#include "oracle/report.h"
#include "raster/errors.h"
#include "raster/file_io.h"
#include "raster/image.h"
#include "raster/scene_loader.h"

namespace raster::cli {
namespace {

namespace fs = std::filesystem;

constexpr const char* kDefaultSceneDir = "corpus/scenes";

struct ReportFlags {
    std::vector<std::string> inputs;
    std::string output_dir;
    std::optional<int> samples;
    bool fast_oracle = false;
    int threads = 0;
};

void register_report_flags(CLI::App& app, ReportFlags& flags) {
    CLI::App* report = app.add_subcommand(
        "report", "Compare scenes with the Embree oracle and write an HTML report (index.html, summary.json, images).");
    report->footer(
        "Inputs are scene files or directories (every .yaml, .yml and .json file in them, sorted); the default is\n"
        "corpus/scenes. Exit code 0 when no scene has a genuine disagreement, 1 when one has, 2 on bad input, 3 when an\n"
        "output cannot be written or Embree fails. Example: raster report corpus/scenes -o report && open report/index.html");
    report->add_option("inputs", flags.inputs, "Scene files or directories (default: corpus/scenes)");
    report->add_option("-o,--output", flags.output_dir, "Directory to write the report into")->required();
    report->add_option("--samples", flags.samples, "Samples per pixel for every scene (default: each scene's own)");
    report->add_flag("--fast-oracle", flags.fast_oracle, "Embree without RTC_SCENE_FLAG_ROBUST (faster, less careful)");
    report->add_option("--threads", flags.threads, "Worker threads, 0 = all cores (results are the same for any count)")
        ->check(CLI::Range(0, 256));
}

bool is_scene_file(const fs::path& path) {
    const std::string ext = path.extension().string();
    return ext == ".yaml" || ext == ".yml" || ext == ".json";
}

// The scene files the inputs name, in order; a directory contributes its scene files sorted by name.
std::vector<fs::path> scene_files(const std::vector<std::string>& inputs) {
    std::vector<fs::path> files;
    for (const std::string& input : inputs) {
        std::error_code error;
        if (fs::is_directory(input, error)) {
            std::vector<fs::path> found;
            for (const auto& entry : fs::directory_iterator(input, error))
                if (entry.is_regular_file() && is_scene_file(entry.path())) found.push_back(entry.path());
            if (error) throw InputError(input, 0, 0, "cannot list the directory: " + error.message());
            if (found.empty()) throw InputError(input, 0, 0, "the directory has no .yaml, .yml or .json scene");
            std::sort(found.begin(), found.end());
            files.insert(files.end(), found.begin(), found.end());
        } else if (fs::exists(input, error)) {
            files.emplace_back(input);
        } else {
            throw InputError(input, 0, 0, "no such scene file or directory");
        }
    }
    return files;
}

// A one-line progress bar, redrawn in place; only used when stderr is a terminal.
class ProgressBar {
public:
    ProgressBar(std::ostream& err, size_t total) : err_(err), total_(total), enabled_(::isatty(STDERR_FILENO) == 1) {}
    void show(size_t done, const std::string& label) {
        if (!enabled_) return;
        constexpr int kWidth = 30;
        const int filled = total_ ? static_cast<int>(kWidth * done / total_) : kWidth;
        err_ << "\r[" << std::string(filled, '#') << std::string(kWidth - filled, '-') << "] " << done << "/" << total_
             << " " << label << "\x1b[K" << std::flush;
    }
    void finish() {
        if (enabled_) err_ << "\r\x1b[K" << std::flush;
    }

private:
    std::ostream& err_;
    size_t total_;
    bool enabled_;
};

int run_report(const ReportFlags& flags, std::ostream& out, std::ostream& err) {
    std::vector<Scene> scenes;
    try {
        const std::vector<fs::path> files =
            scene_files(flags.inputs.empty() ? std::vector<std::string>{kDefaultSceneDir} : flags.inputs);
        for (const fs::path& file : files) {
            Scene scene = load_scene(file);
            if (flags.samples) scene.settings.samples = *flags.samples;
            if (std::string problem = settings_problem(scene.settings); !problem.empty())
                throw InputError(file.string(), 0, 0, problem);
            scenes.push_back(std::move(scene));
        }
    } catch (const InputError& error) {
        err << "raster report: error: " << error.what() << "\n";
        return kExitBadInput;
    }

    const fs::path dir = flags.output_dir;
    std::error_code dir_error;
    fs::create_directories(dir, dir_error);
    if (dir_error) {
        err << "raster report: error: cannot create " << dir << ": " << dir_error.message() << "\n";
        return kExitIoError;
    }
    oracle::ComparisonOptions options;
    options.mode = flags.fast_oracle ? oracle::OracleMode::fast : oracle::OracleMode::robust;
    options.threads = flags.threads;
    std::vector<oracle::ReportRow> rows;
    std::set<std::string> taken;
    ProgressBar progress(err, scenes.size());
    try {
        for (size_t i = 0; i < scenes.size(); ++i) {
            const Scene& scene = scenes[i];
            oracle::ReportRow row;
            row.name = fs::path(scene.path).stem().string();
            progress.show(i, row.name);
            const auto comparison = std::make_unique<oracle::Comparison>(oracle::compare_scene(scene, options));
            const std::string stem = oracle::unique_file_stem(row.name, taken);
            row.raster_image = stem + ".raster.png";
            row.oracle_image = stem + ".oracle.png";
            row.diff_image = stem + ".diff.png";
            write_image(dir / row.raster_image, comparison->raster.image);
            write_image(dir / row.oracle_image, comparison->oracle_image);
            write_image(dir / row.diff_image,
                        oracle::diff_map(comparison->classes, comparison->samples, comparison->raster.image));
            row.comparison = oracle::comparison_json(*comparison);
            char line[256];
            std::snprintf(line, sizeof line, "%s: genuine %llu, ambiguous %llu, max colour error %d, raster %.0f ms, oracle %.0f ms\n",
                          row.name.c_str(), static_cast<unsigned long long>(comparison->counts.genuine_total()),
                          static_cast<unsigned long long>(comparison->counts.ambiguous_total()),
                          comparison->max_color_error, comparison->raster_ms, comparison->oracle_ms);
            progress.finish();
            out << line << std::flush;
            rows.push_back(std::move(row));
        }
        progress.show(scenes.size(), "done");
        progress.finish();
        write_file_atomically(dir / "summary.json", oracle::report_summary(rows).dump(2) + "\n");
        write_file_atomically(dir / "index.html", oracle::report_html(rows));
    } catch (const std::exception& error) {
        progress.finish();
        err << "raster report: error: " << error.what() << "\n";
        return kExitIoError;
    }
    size_t with_genuine = 0;
    for (const auto& row : rows) with_genuine += row.comparison["genuine_total"].get<uint64_t>() > 0;
    out << "report: " << (dir / "index.html").string() << " (" << rows.size() << " scenes, " << with_genuine
        << " with genuine disagreements)\n";
    return with_genuine == 0 ? kExitOk : kExitCheckFailed;
}

}  // namespace

Command add_report_command(CLI::App& app) {
    auto flags = std::make_shared<ReportFlags>();
    register_report_flags(app, *flags);
    return {app.get_subcommand("report"),
            [flags](std::ostream& out, std::ostream& err) { return run_report(*flags, out, err); }};
}

}  // namespace raster::cli
