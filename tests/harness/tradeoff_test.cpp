// Speed against accuracy (`raster tradeoff`): the Pareto front, the exact area, the coverage error and colour RMSE
// falling with more samples, the mode catalogue, the written files, the report's link, and the command's bad input.
#include "harness/tradeoff/tradeoff.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "tests/support/cli_run.h"
#include <nlohmann/json.hpp>

#include "apps/cli.h"
#include "harness/tradeoff/pareto_plot.h"
#include "oracle/report/report.h"
#include "harness/tradeoff/tradeoff_modes.h"
#include "raster/formats/scene_loader.h"
#include "tests/support/temp_dir.h"

namespace raster::harness {
namespace {

namespace fs = std::filesystem;
using test_support::TempDir;

const std::string kCorpus = std::string(RASTER_SOURCE_DIR) + "/corpus/scenes/";

using test_support::CliRun;
using test_support::run_raster;

std::string read_text(const fs::path& path) {
    std::ifstream file(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(file), {});
}

// A corpus scene at a smaller size, written into `dir` (mesh files still read from the corpus).
fs::path small_scene(const TempDir& dir, const std::string& corpus_name, int width, int height) {
    std::string text = read_text(kCorpus + corpus_name);
    const std::string meshes = kCorpus + "../meshes/";
    for (size_t at = text.find("../meshes/"); at != std::string::npos; at = text.find("../meshes/", at + meshes.size()))
        text.replace(at, 10, meshes);
    const size_t image = text.find("image: {width: ");
    const size_t end = text.find(',', text.find("height: ", image));
    EXPECT_NE(image, std::string::npos);
    text.replace(image, end - image, "image: {width: " + std::to_string(width) + ", height: " + std::to_string(height));
    return dir.write(corpus_name, text);
}

// A scene seen by a 90-degree camera from (0, 0, 5) on a 100 x 100 image: the plane z = 0 maps to the screen by
// (x, y) -> (50 + 10 x, 50 - 10 y), so areas are easy to work out by hand.
Scene hand_scene(const std::string& vertices, const std::string& faces) {
    const std::string text =
        "image: {width: 100, height: 100}\ncamera: {eye: [0, 0, 5], target: [0, 0, 0], fov: 90}\n"
        "render: {shading: unlit}\nmeshes:\n  - vertices: " +
        vertices + "\n    faces: " + faces + "\n";
    return parse_scene(text, "hand.yaml");
}

// A small XML well-formedness check: tags nest and close, attribute values are quoted, '&' starts an entity.
bool well_formed_xml(const std::string& xml, std::string& problem) {
    std::vector<std::string> open;
    size_t at = 0;
    if (xml.rfind("<?xml", 0) == 0) at = xml.find("?>") + 2;
    while (at < xml.size()) {
        if (xml[at] == '&') {
            const size_t semi = xml.find(';', at);
            if (semi == std::string::npos || semi - at > 8) return problem = "bare & at " + std::to_string(at), false;
            at = semi + 1;
            continue;
        }
        if (xml[at] != '<') {
            ++at;
            continue;
        }
        const size_t close = xml.find('>', at);
        if (close == std::string::npos) return problem = "unclosed tag at " + std::to_string(at), false;
        std::string tag = xml.substr(at + 1, close - at - 1);
        int quotes = 0;
        for (char c : tag) quotes += c == '"';
        if (quotes % 2) return problem = "odd quotes in <" + tag + ">", false;
        if (tag.find('<') != std::string::npos) return problem = "'<' inside <" + tag + ">", false;
        if (!tag.empty() && tag[0] == '/') {
            const std::string name = tag.substr(1);
            if (open.empty() || open.back() != name) return problem = "</" + name + "> closes nothing open", false;
            open.pop_back();
        } else if (!tag.empty() && tag.back() != '/') {
            open.push_back(tag.substr(0, tag.find_first_of(" \n")));
        }
        at = close + 1;
    }
    if (!open.empty()) return problem = "<" + open.back() + "> never closed", false;
    return true;
}

size_t occurrences(const std::string& text, const std::string& needle) {
    size_t n = 0;
    for (size_t at = text.find(needle); at != std::string::npos; at = text.find(needle, at + 1)) ++n;
    return n;
}

std::vector<std::string> split(const std::string& line, char separator) {
    std::vector<std::string> fields;
    std::stringstream stream(line);
    for (std::string field; std::getline(stream, field, separator);) fields.push_back(field);
    return fields;
}

TEST(TradeoffPareto, aDominatedPointIsOffTheFront) {
    // (3, 4) is slower and worse than (2, 3); the others each win on one axis.
    EXPECT_EQ(pareto_front({{1, 5}, {2, 3}, {3, 4}, {4, 1}}), (std::vector<bool>{true, true, false, true}));
    EXPECT_EQ(pareto_front({{5, 5}, {1, 1}}), (std::vector<bool>{false, true}));
    EXPECT_EQ(pareto_front({}), std::vector<bool>{});
}

TEST(TradeoffPareto, tiesAreDecidedByTheOtherAxisAndEqualPointsAllStay) {
    // Same time, worse error: dominated. Same error, slower: dominated. Identical points: both on the front.
    EXPECT_EQ(pareto_front({{1, 5}, {1, 4}}), (std::vector<bool>{false, true}));
    EXPECT_EQ(pareto_front({{2, 3}, {3, 3}}), (std::vector<bool>{true, false}));
    EXPECT_EQ(pareto_front({{2, 3}, {2, 3}, {4, 4}}), (std::vector<bool>{true, true, false}));
    EXPECT_EQ(pareto_front({{NAN, 0}, {1, 1}}), (std::vector<bool>{false, true}));
}

TEST(TradeoffMeasures, theMedianTakesTheMiddleOrTheMeanOfTheTwoMiddleValues) {
    EXPECT_EQ(median({5, 1, 3}), 3);
    EXPECT_EQ(median({4, 1, 3, 100}), 3.5);
    EXPECT_EQ(median({}), 0);
}

TEST(TradeoffMeasures, colourRmseIsOverEveryPixelAndRgbChannel) {
    Image a(2, 1, 3), b(2, 1, 3);
    b.pixels[4] = 6;  // one channel of six apart by 6: sqrt(36 / 6)
    EXPECT_DOUBLE_EQ(color_rmse(a, b), std::sqrt(6.0));
    EXPECT_DOUBLE_EQ(color_rmse(a, a), 0.0);
    EXPECT_THROW(color_rmse(a, Image(1, 2, 3)), std::invalid_argument);
}

TEST(TradeoffMeasures, theReferenceImageMustFitTheFrameMemoryCap) {
    RenderSettings settings;
    settings.width = settings.height = 800;
    EXPECT_EQ(reference_problem(settings, 16), "");  // 800 * 800 * 256 * 20 bytes: 3.1 GiB
    settings.width = settings.height = 1200;         // 7 GiB
    EXPECT_NE(reference_problem(settings, 16).find("--reference-grid"), std::string::npos);
    EXPECT_EQ(reference_problem(settings, 8), "");
}

TEST(TradeoffMeasures, theExactAreaIsTheHandComputedAreaClippedToTheViewport) {
    // Screen (50, 50), (70, 50), (50, 20): legs of 20 and 30 px.
    const Scene inside = hand_scene("[[0, 0, 0], [2, 0, 0], [0, 3, 0]]", "[[0, 1, 2]]");
    const std::vector<double> areas =
        exact_triangle_areas(inside);
    ASSERT_EQ(areas.size(), 1u);
    EXPECT_NEAR(areas[0], 300.0, 1e-3);
    // Screen (50, 50), (150, 50), (50, -50): the viewport keeps the square [50, 100] x [0, 50]. The second triangle
    // is behind the camera.
    const Scene clipped =
        hand_scene("[[0, 0, 0], [10, 0, 0], [0, 10, 0], [0, 0, 6], [1, 0, 6], [0, 1, 6]]", "[[0, 1, 2], [3, 4, 5]]");
    const std::vector<double> clipped_areas =
        exact_triangle_areas(clipped);
    ASSERT_EQ(clipped_areas.size(), 2u);
    EXPECT_NEAR(clipped_areas[0], 2500.0, 1e-2);
    EXPECT_EQ(clipped_areas[1], 0.0);
}

TEST(TradeoffMeasures, coveredSamplesOverSamplesPerPixelApproachTheExactArea) {
    Scene scene = hand_scene("[[0, 0, 0], [2, 0, 0], [0, 3, 0]]", "[[0, 1, 2]]");
    const std::vector<double> areas =
        exact_triangle_areas(scene);
    scene.settings.samples = 256;
    scene.settings.pattern = SamplePattern::grid;
    const std::vector<uint64_t> covered =
        covered_sample_counts(scene, run_vertex_stage(scene, vertex_stage_needs(scene.settings.shading)), 2);
    ASSERT_EQ(covered.size(), 1u);
    EXPECT_NEAR(double(covered[0]) / 256.0, 300.0, 0.5);  // a 16 x 16 grid on a 100 px perimeter
    EXPECT_NEAR(coverage_error(covered, 256, areas), 0.0, 0.5 / 300.0);
    EXPECT_DOUBLE_EQ(coverage_error({10, 0}, 1, {5.0, 5.0}), 1.0);  // |10 - 5| + |0 - 5| over 10
    EXPECT_DOUBLE_EQ(coverage_error({0}, 4, {0.0}), 0.0);
}

TradeoffOptions quick_options() {
    TradeoffOptions options;
    options.runs = 1;
    options.reference_grid = 8;
    return options;
}

std::vector<const TradeoffMode*> named_modes(const std::vector<std::string>& names) {
    std::vector<const TradeoffMode*> modes;
    for (const std::string& name : names) {
        modes.push_back(find_tradeoff_mode(name));
        EXPECT_NE(modes.back(), nullptr) << name;
    }
    return modes;
}

TEST(TradeoffMeasures, moreSamplesGiveLowerCoverageErrorAndColourRmseThanOne) {
    // The teapot at 128 x 128: thousands of small triangles with edges in every direction, so the sampled areas'
    // errors are statistical, not the luck of a few long edges against the sample lattice.
    TempDir dir;
    const Scene scene = load_scene(small_scene(dir, "teapot.yaml", 128, 128));
    const SceneTradeoff result =
        measure_scene(scene, named_modes({"samples1", "samples4", "samples16", "grid4x4"}), quick_options());
    ASSERT_EQ(result.modes.size(), 4u);
    const ModeResult& one = result.modes[0];
    EXPECT_EQ(one.settings.samples, 1);
    EXPECT_EQ(one.samples, 128u * 128u);
    EXPECT_EQ(one.times_ms.size(), 1u);
    EXPECT_GT(one.color_rmse, 0.0);
    EXPECT_GT(result.exact_area, 0.0);
    for (size_t i = 1; i < result.modes.size(); ++i) {
        const ModeResult& more = result.modes[i];
        EXPECT_LT(more.coverage_error, one.coverage_error) << more.mode;
        EXPECT_LT(more.color_rmse, one.color_rmse) << more.mode;
        EXPECT_EQ(more.samples, 128u * 128u * uint64_t(more.settings.samples)) << more.mode;
    }
}

TEST(TradeoffMeasures, sixteenSamplesGiveALowerColourRmseThanOneOnTheCorpusScenes) {
    TempDir dir;
    for (const char* name : {"single_triangle.yaml", "perspective_quad.yaml"}) {
        const Scene scene = load_scene(small_scene(dir, name, 96, 64));
        const SceneTradeoff result = measure_scene(scene, named_modes({"samples1", "samples16"}), quick_options());
        ASSERT_EQ(result.modes.size(), 2u);
        EXPECT_LT(result.modes[1].color_rmse, result.modes[0].color_rmse) << name;
    }
}

TEST(TradeoffMeasures, affineInterpolationHasALargerColourRmseThanPerspectiveOnThePerspectiveQuad) {
    TempDir dir;
    const Scene scene = load_scene(small_scene(dir, "perspective_quad.yaml", 120, 80));
    const SceneTradeoff result = measure_scene(scene, named_modes({"perspective", "affine"}), quick_options());
    ASSERT_EQ(result.modes.size(), 2u);
    EXPECT_GT(result.modes[1].color_rmse, 2.0 * result.modes[0].color_rmse + 1.0);
    EXPECT_GT(result.modes[1].genuine, 0u);  // the oracle's barycentrics are perspective-correct
    EXPECT_EQ(result.modes[0].genuine, 0u);
}

TEST(TradeoffModes, namesAreUniqueAndEachModeChangesWhatItsNameSays) {
    std::set<std::string> names;
    for (const TradeoffMode& mode : tradeoff_modes()) EXPECT_TRUE(names.insert(mode.name).second) << mode.name;
    EXPECT_EQ(find_tradeoff_mode("no-such-mode"), nullptr);
    const RenderSettings base;
    EXPECT_EQ(apply_mode(*find_tradeoff_mode("snap4"), base).snap_bits, 4);
    const RenderSettings grid = apply_mode(*find_tradeoff_mode("grid8x8"), base);
    EXPECT_EQ(grid.samples, 64);
    EXPECT_EQ(grid.pattern, SamplePattern::grid);
    EXPECT_EQ(apply_mode(*find_tradeoff_mode("edges-float"), base).modes.edges, EdgeArithmetic::float32);
    EXPECT_EQ(apply_mode(*find_tradeoff_mode("affine"), base).modes.interpolation, Interpolation::affine);
    EXPECT_EQ(apply_mode(*find_tradeoff_mode("depth-fixed24"), base).modes.depth, DepthFormat::fixed24);
    EXPECT_EQ(apply_mode(*find_tradeoff_mode("guard-band"), base).modes.clipping, Clipping::guard_band);
    EXPECT_FALSE(apply_mode(*find_tradeoff_mode("hiz-off"), base).modes.hierarchical_z);
    const RenderSettings fastest = apply_mode(*find_tradeoff_mode("fastest"), base);
    EXPECT_EQ(fastest.snap_bits, 4);
    EXPECT_EQ(fastest.samples, 1);
    EXPECT_EQ(fastest.modes.edges, EdgeArithmetic::float32);
    EXPECT_EQ(fastest.modes.interpolation, Interpolation::affine);
    EXPECT_EQ(fastest.modes.depth, DepthFormat::fixed24);
    EXPECT_EQ(fastest.modes.clipping, Clipping::guard_band);
}

TEST(TradeoffModes, theDefaultSweepLeavesOutModesThatRepeatTheBaseline) {
    auto names = [](const std::vector<const TradeoffMode*>& sweep) {
        std::set<std::string> out;
        for (const TradeoffMode* mode : sweep) out.insert(mode->name);
        return out;
    };
    const std::set<std::string> defaults = names(default_sweep(RenderSettings{}));  // 8 bits, 1 sample, fixed, ...
    for (const char* kept :
         {"baseline", "snap4", "samples4", "grid8x8", "edges-float", "affine", "hiz-off", "fastest", "exact"})
        EXPECT_TRUE(defaults.count(kept)) << kept;
    for (const char* repeat :
         {"snap8", "samples1", "edges-fixed", "perspective", "depth-reversed-z", "clip-full", "hiz-on"})
        EXPECT_FALSE(defaults.count(repeat)) << repeat;
    RenderSettings four;
    four.samples = 4;
    const std::set<std::string> with_four = names(default_sweep(four));
    EXPECT_TRUE(with_four.count("samples1"));
    EXPECT_FALSE(with_four.count("samples4"));
}

TEST(TradeoffCli, writesParsableCsvJsonAndSvgWholeAndOnlyThose) {
    TempDir dir;
    const fs::path scene = small_scene(dir, "single_triangle.yaml", 64, 48);
    const fs::path out = dir / "out";
    fs::create_directories(out);
    std::ofstream(out / "tradeoff.json") << "stale";
    const CliRun r = run_raster({"tradeoff", scene.string(), "-o", out.string(), "--modes", "baseline,samples4,fastest",
                             "--runs", "1", "--reference-grid", "4"});
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.out.find("samples4"), std::string::npos) << r.out;
    std::set<std::string> files;
    for (const auto& entry : fs::directory_iterator(out)) files.insert(entry.path().filename().string());
    EXPECT_EQ(files, (std::set<std::string>{"tradeoff.json", "tradeoff.csv", "pareto.svg"}));  // no temporaries left

    const nlohmann::json json = nlohmann::json::parse(read_text(out / "tradeoff.json"));
    EXPECT_EQ(json["runs"], 1);
    EXPECT_EQ(json["reference"]["samples_per_pixel"], 16);
    ASSERT_EQ(json["scenes"].size(), 1u);
    const nlohmann::json& s = json["scenes"][0];
    EXPECT_EQ(s["name"], "single_triangle");
    ASSERT_EQ(s["modes"].size(), 3u);
    size_t on_front = 0;
    for (const nlohmann::json& m : s["modes"]) {
        for (const char* key : {"mode", "settings", "median_ms", "times_ms", "samples", "genuine", "ambiguous",
                                "color_rmse", "coverage_error", "on_front"})
            EXPECT_TRUE(m.contains(key)) << key;
        on_front += m["on_front"].get<bool>();
    }
    EXPECT_EQ(s["modes"][1]["settings"]["samples"], 4);
    EXPECT_EQ(s["modes"][2]["settings"]["edges"], "float");
    EXPECT_EQ(s["front"].size(), on_front);
    EXPECT_GE(on_front, 1u);

    const std::vector<std::string> lines = split(read_text(out / "tradeoff.csv"), '\n');
    ASSERT_EQ(lines.size(), 4u);
    const std::vector<std::string> header = split(lines[0], ',');
    EXPECT_EQ(header.front(), "scene");
    EXPECT_EQ(header.back(), "on_front");
    for (size_t i = 1; i < lines.size(); ++i) EXPECT_EQ(split(lines[i], ',').size(), header.size()) << lines[i];
    EXPECT_EQ(split(lines[2], ',')[1], "samples4");

    const std::string svg = read_text(out / "pareto.svg");
    std::string problem;
    EXPECT_TRUE(well_formed_xml(svg, problem)) << problem;
    EXPECT_EQ(occurrences(svg, "<circle class=\"mode"), 3u);
    EXPECT_EQ(occurrences(svg, "class=\"mode on-front\""), on_front);
    EXPECT_NE(svg.find("<path class=\"front\""), std::string::npos);
    EXPECT_NE(svg.find("Pareto front, fastest first: "), std::string::npos);
}

TEST(TradeoffCli, theSvgEscapesNamesAndStaysWellFormed) {
    SceneTradeoff scene;
    scene.name = "a<b>&\"c\"";
    ModeResult m;
    m.mode = "x&y";
    m.median_ms = 2;
    m.color_rmse = 1;
    m.on_front = true;
    scene.modes = {m};
    const std::string svg = pareto_svg({scene, SceneTradeoff{}}, 8);
    std::string problem;
    EXPECT_TRUE(well_formed_xml(svg, problem)) << problem;
    EXPECT_EQ(svg.find("a<b>"), std::string::npos);
    EXPECT_NE(svg.find("x&amp;y"), std::string::npos);
}

TEST(TradeoffCli, helpNamesEveryFlagAndListModesNamesEveryMode) {
    const CliRun help = run_raster({"tradeoff", "--help"});
    EXPECT_EQ(help.code, 0);
    for (const char* flag :
         {"-o", "--modes", "--runs", "--reference-grid", "--fast-oracle", "--threads", "--list-modes"})
        EXPECT_NE(help.out.find(flag), std::string::npos) << flag;
    const CliRun list = run_raster({"tradeoff", "--list-modes"});
    EXPECT_EQ(list.code, 0);
    for (const TradeoffMode& mode : tradeoff_modes())
        EXPECT_NE(list.out.find(mode.name + " "), std::string::npos) << mode.name;
}

TEST(TradeoffCli, badInputExitsTwoNamingTheProblemAndWritesNothing) {
    TempDir dir;
    const fs::path out = dir / "out";
    const CliRun missing = run_raster({"tradeoff", (dir / "missing.yaml").string(), "-o", out.string()});
    EXPECT_EQ(missing.code, 2);
    EXPECT_NE(missing.err.find("missing.yaml"), std::string::npos) << missing.err;

    const CliRun unknown =
        run_raster({"tradeoff", kCorpus + "single_triangle.yaml", "-o", out.string(), "--modes", "baseline,snap5"});
    EXPECT_EQ(unknown.code, 2);
    EXPECT_NE(unknown.err.find("unknown mode 'snap5'"), std::string::npos) << unknown.err;
    EXPECT_NE(unknown.err.find("grid8x8"), std::string::npos) << unknown.err;  // lists the known ones

    const fs::path huge = small_scene(dir, "single_triangle.yaml", 4000, 4000);
    const CliRun too_big = run_raster({"tradeoff", huge.string(), "--reference-grid", "16", "-o", out.string()});
    EXPECT_EQ(too_big.code, 2);
    EXPECT_NE(too_big.err.find("single_triangle.yaml"), std::string::npos) << too_big.err;
    EXPECT_NE(too_big.err.find("--reference-grid"), std::string::npos) << too_big.err;

    EXPECT_EQ(run_raster({"tradeoff", "-o", out.string()}).code, 2);  // no scene
    EXPECT_EQ(run_raster({"tradeoff", kCorpus + "single_triangle.yaml", "--runs", "0", "-o", out.string()}).code, 2);
    EXPECT_EQ(run_raster({"tradeoff", kCorpus + "single_triangle.yaml", "--reference-grid", "17", "-o", out.string()}).code,
              2);
    EXPECT_FALSE(fs::exists(out));
}

TEST(TradeoffCli, anOutputThatCannotBeWrittenExitsThree) {
    TempDir dir;
    const fs::path scene = small_scene(dir, "single_triangle.yaml", 16, 12);
    const fs::path blocker = dir.write("blocker", "a file where the output directory should be");
    const CliRun r = run_raster({"tradeoff", scene.string(), "-o", (blocker / "out").string(), "--modes", "baseline",
                             "--runs", "1", "--reference-grid", "2"});
    EXPECT_EQ(r.code, 3);
    EXPECT_NE(r.err.find("blocker"), std::string::npos) << r.err;
}

TEST(TradeoffReport, theReportLinksThePlotAndTheTable) {
    TempDir dir;
    const fs::path scene = small_scene(dir, "single_triangle.yaml", 32, 24);
    const fs::path results = dir / "results";
    ASSERT_EQ(run_raster({"tradeoff", scene.string(), "-o", results.string(), "--modes", "baseline,samples4", "--runs", "1",
                      "--reference-grid", "2"})
                  .code,
              0);
    const fs::path report = dir / "report";
    const CliRun r = run_raster({"report", scene.string(), "-o", report.string(), "--tradeoff", results.string()});
    ASSERT_EQ(r.code, 0) << r.err;
    const std::string html = read_text(report / "index.html");
    EXPECT_NE(html.find("src=\"tradeoff/pareto.svg\""), std::string::npos);
    EXPECT_NE(html.find("href=\"tradeoff/tradeoff.csv\""), std::string::npos);
    EXPECT_EQ(occurrences(html, "<table class=\"tradeoff\""), 1u);
    EXPECT_NE(html.find(">samples4</td>"), std::string::npos);
    for (const char* name : {"pareto.svg", "tradeoff.csv", "tradeoff.json"})
        EXPECT_TRUE(fs::is_regular_file(report / "tradeoff" / name))
            << name;  // copied: the report stays self-contained
    EXPECT_EQ(nlohmann::json::parse(read_text(report / "summary.json"))["tradeoff"], "tradeoff/tradeoff.json");

    // Run again without --tradeoff: the copy now in report/tradeoff/ is found and linked in place.
    ASSERT_EQ(run_raster({"report", scene.string(), "-o", report.string()}).code, 0);
    EXPECT_NE(read_text(report / "index.html").find("src=\"tradeoff/pareto.svg\""), std::string::npos);

    // A report without trade-off results has no such section; a --tradeoff folder without results is bad input.
    const fs::path plain = dir / "plain";
    ASSERT_EQ(run_raster({"report", scene.string(), "-o", plain.string()}).code, 0);
    EXPECT_EQ(read_text(plain / "index.html").find("Speed against accuracy"), std::string::npos);
    const CliRun bad =
        run_raster({"report", scene.string(), "-o", (dir / "bad").string(), "--tradeoff", (dir / "none").string()});
    EXPECT_EQ(bad.code, 2);
    EXPECT_NE(bad.err.find("tradeoff.json"), std::string::npos) << bad.err;
    EXPECT_FALSE(fs::exists(dir / "bad"));
}

TEST(TradeoffReport, theSectionMarksTheFrontAndSurvivesMistypedFields) {
    const nlohmann::json results = {{"runs", 5},
                                    {"reference", {{"samples_per_pixel", 64}}},
                                    {"scenes",
                                     {{{"name", "teapot<1>"},
                                       {"modes",
                                        {{{"mode", "fastest"},
                                          {"median_ms", 1.5},
                                          {"genuine", 3},
                                          {"ambiguous", 4},
                                          {"color_rmse", 9.25},
                                          {"coverage_error", 0.01},
                                          {"on_front", true}},
                                         {{"mode", "slow"}, {"median_ms", "not a number"}, {"on_front", false}},
                                         42}}}}}};
    const std::string html = oracle::report_html({}, oracle::TradeoffLink{"tradeoff", results});
    EXPECT_NE(html.find("Speed against accuracy"), std::string::npos);
    EXPECT_NE(html.find("teapot&lt;1&gt;"), std::string::npos);
    EXPECT_EQ(occurrences(html, "<tr class=\"on-front\">"), 1u);
    EXPECT_NE(html.find("<td>9.250</td>"), std::string::npos);
    EXPECT_NE(html.find(">slow</td><td>-</td>"), std::string::npos);
    EXPECT_EQ(oracle::report_html({}).find("Speed against accuracy"), std::string::npos);
}

}  // namespace
}  // namespace raster::harness
