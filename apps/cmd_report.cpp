// `raster report`: compares many scenes with the oracle and writes index.html, a page per scene, summary.json and the
// images.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <set>

#include <nlohmann/json.hpp>

#include "apps/backends.h"
#include "backends/plugin/plugin_library.h"
#include "apps/command.h"
#include "apps/settings_flags.h"
#include "apps/progress_bar.h"
#include "apps/render_outputs.h"
#include "harness/comparison/comparison_output.h"
#include "harness/comparison/junit_report.h"
#include "oracle/compare/diff_map.h"
#include "oracle/reference/embree_device.h"
#include "oracle/report/report.h"
#include "oracle/report/scene_page.h"
#include "raster/core/errors.h"
#include "raster/core/file_io.h"
#include "raster/image/image.h"
#include "raster/compat/scene_loader.h"
#include "raster/scene/validation.h"

namespace raster::cli {
namespace {

namespace fs = std::filesystem;

constexpr const char* kDefaultSceneDir = "corpus/scenes";
// The samples a scene page's inspector has evidence for, in whole pixels (the pixels past them are counted): about
// 200 bytes of evidence each, so a page's evidence stays under about 10 MB whatever the frame.
constexpr size_t kEvidenceSamples = 50000;

struct ReportFlags {
    std::vector<std::string> inputs;
    std::string output_dir;
    std::optional<int> samples;
    bool fast_oracle = false;
    int threads = 0;
    std::string tradeoff_dir;
    std::string junit_out;
    std::vector<std::string> backends = {"raster"};
};

void register_report_flags(CLI::App& app, ReportFlags& flags) {
    CLI::App* report = app.add_subcommand(
        "report", "Compare scenes with the Embree oracle and write an HTML report (index.html, a page per scene, summary.json, "
                  "images).");
    report->footer(
        "Inputs are scene files, mesh files (.obj, .ply, framed by a default camera and light) or directories (every\n"
        ".yaml, .yml and .json file in them, sorted: the meshes beside a scene are not scenes); the default is\n"
        "corpus/scenes. Exit code 0 when no scene has a genuine disagreement, 1 when one has, 2 on bad input, 3 when an\n"
        "output cannot be written or Embree fails. Example: raster report corpus/scenes -o report && open report/index.html");
    report->add_option("inputs", flags.inputs, "Scene files or directories (default: corpus/scenes)");
    report->add_option("-o,--output", flags.output_dir, "Directory to write the report into")->required();
    report->add_option("--samples", flags.samples, "Samples per pixel for every scene (default: each scene's own)");
    add_fast_oracle_flag(*report, flags.fast_oracle);
    report->add_option("--backend", flags.backends,
                       "What renders each scene, one row and page per backend: raster (the default), gl, "
                       "plugin:PATH, or several (--backend raster,gl); a scene a backend cannot draw is skipped for "
                       "it, saying why")
        ->delimiter(',')
        ->check(backend_name_validator());
    report->add_option("--threads", flags.threads, "Worker threads, 0 = all cores (results are the same for any count)")
        ->check(CLI::Range(0, 256));
    report->add_option("--junit", flags.junit_out,
                       "Also write the verdicts as JUnit XML to this file: a test case per scene, failed when it has "
                       "genuine disagreements, for CI systems");
    report->add_option("--tradeoff", flags.tradeoff_dir,
                       "Link the results of `raster tradeoff -o DIR` (copied into OUTPUT/tradeoff/); without it, "
                       "OUTPUT/tradeoff/tradeoff.json is linked when it exists");
}

bool is_scene_file(const fs::path& path) {
    const std::string ext = path.extension().string();
    // glTF models are scenes of their own; OBJ and PLY files in a folder are usually the meshes its scenes name.
    return ext == ".yaml" || ext == ".yml" || ext == ".json" || ext == ".gltf" || ext == ".glb";
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
            if (found.empty()) throw InputError(input, 0, 0, "the directory has no .yaml, .yml, .json, .gltf or .glb scene");
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

// The files of a `raster tradeoff` run that the report links.
constexpr const char* kTradeoffFiles[] = {"tradeoff.json", "tradeoff.csv", "pareto.svg"};
constexpr uint64_t kMaxTradeoffFileBytes = uint64_t{256} << 20;

// Reads DIR/tradeoff.json: an object with a "scenes" array. Throws InputError naming the file otherwise.
nlohmann::json read_tradeoff_results(const fs::path& dir) {
    const fs::path file = dir / "tradeoff.json";
    const std::string text = read_file_bytes(file, kMaxTradeoffFileBytes);
    nlohmann::json results = nlohmann::json::parse(text, nullptr, false);
    if (results.is_discarded() || !results.is_object() || !results.contains("scenes") || !results["scenes"].is_array())
        throw InputError(file.string(), 0, 0,
                         "not the tradeoff.json of `raster tradeoff` (an object with a scenes array)");
    return results;
}

// The trade-off results to link, from --tradeoff DIR (every file must be there) or, without it, from
// OUTPUT/tradeoff/ when that holds a tradeoff.json. Throws InputError for an explicit DIR that is unusable.
std::optional<nlohmann::json> find_tradeoff_results(const ReportFlags& flags, std::ostream& err) {
    if (!flags.tradeoff_dir.empty()) {
        for (const char* name : kTradeoffFiles)
            if (!fs::is_regular_file(fs::path(flags.tradeoff_dir) / name))
                throw InputError((fs::path(flags.tradeoff_dir) / name).string(), 0, 0,
                                 "no such file (run `raster tradeoff SCENE... -o " + flags.tradeoff_dir + "` first)");
        return read_tradeoff_results(flags.tradeoff_dir);
    }
    const fs::path in_place = fs::path(flags.output_dir) / "tradeoff";
    if (!fs::is_regular_file(in_place / "tradeoff.json")) return std::nullopt;
    try {
        return read_tradeoff_results(in_place);
    } catch (const InputError& error) {
        err << "raster report: warning: not linking the trade-off results: " << error.what() << "\n";
        return std::nullopt;
    }
}

// Copies the trade-off files into OUTPUT/tradeoff/ (each written whole), unless they are already there.
void copy_tradeoff_files(const fs::path& from, const fs::path& report_dir) {
    const fs::path to = report_dir / "tradeoff";
    std::error_code error;
    if (fs::equivalent(from, to, error)) return;
    fs::create_directories(to, error);
    if (error) throw std::runtime_error("cannot create " + to.string() + ": " + error.message());
    for (const char* name : kTradeoffFiles)
        write_file_atomically(to / name, read_file_bytes(from / name, kMaxTradeoffFileBytes));
}

int run_report(const ReportFlags& flags, std::ostream& out, std::ostream& err) {
    std::vector<SceneFile> scenes;
    std::optional<nlohmann::json> tradeoff;
    try {
        tradeoff = find_tradeoff_results(flags, err);
        const std::vector<fs::path> files =
            scene_files(flags.inputs.empty() ? std::vector<std::string>{kDefaultSceneDir} : flags.inputs);
        for (const fs::path& file : files) {
            SceneFile scene_file = load_scene_file(file);
            if (scene_file.request.self_check)
                throw InputError(file.string(), 0, 0,
                                 "this file asks for a check of its own, not an image: `raster render` writes "
                                 "nothing to compare");
            Scene& scene = scene_file.scene;
            if (flags.samples) scene.settings.samples = *flags.samples;
            if (std::string problem = settings_problem(scene.settings); !problem.empty())
                throw InputError(file.string(), 0, 0, problem);
            if (std::string problem = harness::comparison_problem(scene); !problem.empty())
                throw InputError(file.string(), 0, 0, problem);
            scenes.push_back(std::move(scene_file));
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
    harness::ComparisonOptions options;
    options.mode = flags.fast_oracle ? oracle::OracleMode::fast : oracle::OracleMode::robust;
    options.threads = flags.threads;
    std::vector<std::unique_ptr<Renderer>> renderers;
    try {
        for (const std::string& backend : flags.backends) renderers.push_back(renderer_named(backend));
    } catch (const InputError& error) {
        err << "raster report: error: " << error.what() << "\n";
        return kExitBadInput;
    }
    std::vector<oracle::ReportRow> rows;
    std::vector<harness::JunitCase> junit_cases;
    const std::string started = harness::junit_timestamp_now();
    std::set<std::string> taken = {"index"};  // a scene named index gets index-2.html, not the index's name
    size_t skipped = 0;  // scenes a backend cannot draw
    size_t failed = 0;   // scenes a plugin failed on
    ProgressBar progress(err, scenes.size());
    try {
        for (size_t i = 0; i < scenes.size(); ++i)
            for (size_t b = 0; b < renderers.size(); ++b) {
                const Scene& scene = scenes[i].scene;
                // What `raster render` writes for the file: its colour image unless it asks for the depth image.
                options.colour_output = image_kind_for(scenes[i].request) == OutputKind::colour;
                options.evidence_pixels = kEvidenceSamples / size_t(std::max(scene.settings.samples, 1));
                options.renderer = renderers[b].get();
                const std::string backend = backend_label(flags.backends[b]);
                oracle::ReportRow row;
                const std::string stem_name = fs::path(scene.path).stem().string();
                row.name = backend == "raster" ? stem_name : stem_name + " (" + backend + ")";
                progress.show(i, row.name);
                std::unique_ptr<harness::Comparison> comparison;
                try {
                    comparison = std::make_unique<harness::Comparison>(harness::compare_scene(scene, options));
                } catch (const InputError& error) {  // what this backend cannot draw: the other rows go on
                    progress.finish();
                    out << row.name << ": skipped: " << error.what() << "\n" << std::flush;
                    ++skipped;
                    continue;
                } catch (const plugin::PluginError& error) {  // the plugin failed on this scene: it fails the report
                    progress.finish();
                    out << row.name << ": failed: " << error.what() << "\n" << std::flush;
                    ++failed;
                    continue;
                }
                const std::string stem =
                    oracle::unique_file_stem(backend == "raster" ? stem_name : stem_name + "-" + backend, taken);
                row.raster_image = stem + ".raster.png";
                row.oracle_image = stem + ".oracle.png";
                row.diff_image = stem + ".diff.png";
                row.page = stem + ".html";
                row.evidence = stem + ".evidence.js";
                write_image(dir / row.raster_image, comparison->raster.image, flags.threads);
                write_image(dir / row.oracle_image, comparison->oracle_image, flags.threads);
                write_image(dir / row.diff_image, harness::diff_map(*comparison), flags.threads);
                row.comparison = harness::comparison_json(*comparison);
                write_file_atomically(dir / row.evidence,
                                      "window.rasterEvidence = " + comparison->evidence.dump() + ";\n");
                write_file_atomically(dir / row.page, oracle::scene_page_html(row));
                junit_cases.push_back(
                    harness::junit_case(*comparison, backend == "raster" ? scene.path : scene.path + " (" + backend + ")"));
                char line[256];
                std::snprintf(line, sizeof line,
                              "%s: genuine %llu, ambiguous %llu, colour genuine %llu, raster %.0f ms, oracle %.0f ms\n",
                              row.name.c_str(), static_cast<unsigned long long>(comparison->genuine_total()),
                              static_cast<unsigned long long>(comparison->visibility.counts.ambiguous_total()),
                              static_cast<unsigned long long>(comparison->colour.genuine_pixels), comparison->raster_ms,
                              comparison->oracle_ms);
                progress.finish();
                out << line << std::flush;
                rows.push_back(std::move(row));
            }
        progress.show(scenes.size(), "done");
        progress.finish();
        std::optional<oracle::TradeoffLink> link;
        nlohmann::json summary = oracle::report_summary(rows);
        if (tradeoff) {
            if (!flags.tradeoff_dir.empty()) copy_tradeoff_files(flags.tradeoff_dir, dir);
            link = oracle::TradeoffLink{"tradeoff", std::move(*tradeoff)};
            summary["tradeoff"] = "tradeoff/tradeoff.json";
        }
        write_file_atomically(dir / "summary.json", summary.dump(2) + "\n");
        write_file_atomically(dir / "index.html", oracle::report_html(rows, link));
        if (!flags.junit_out.empty())
            write_file_atomically(flags.junit_out, harness::junit_xml("raster report", junit_cases, started,
                                                                      harness::junit_hostname()));
    } catch (const std::exception& error) {
        progress.finish();
        err << "raster report: error: " << error.what() << "\n";
        return kExitIoError;
    }
    size_t with_genuine = 0;
    for (const auto& row : rows) with_genuine += row.comparison["genuine_total"].get<uint64_t>() > 0;
    out << "report: " << (dir / "index.html").string() << " (" << rows.size() << " scenes, " << with_genuine
        << " with genuine disagreements" << (skipped ? ", " + std::to_string(skipped) + " skipped" : std::string())
        << (failed ? ", " + std::to_string(failed) + " on which the plugin failed" : std::string()) << ")\n";
    return with_genuine == 0 && failed == 0 ? kExitOk : kExitCheckFailed;
}

}  // namespace

Command add_report_command(CLI::App& app) {
    return flags_command<ReportFlags>(app, "report", register_report_flags, run_report);
}

}  // namespace raster::cli
