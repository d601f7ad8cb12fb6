// `raster tradeoff` on the command line: the CSV, JSON and SVG it writes, its help, and its bad input.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "harness/tradeoff/pareto_plot.h"
#include "harness/tradeoff/tradeoff.h"
#include "harness/tradeoff/tradeoff_modes.h"
#include "tests/support/cli_run.h"
#include "tests/support/tradeoff_test_support.h"

namespace raster::harness {
namespace {

using namespace tradeoff_test;
using test_support::CliRun;
using test_support::run_raster;

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

std::vector<std::string> split(const std::string& line, char separator) {
    std::vector<std::string> fields;
    std::stringstream stream(line);
    for (std::string field; std::getline(stream, field, separator);) fields.push_back(field);
    return fields;
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
    EXPECT_EQ(s["modes"][2]["settings"]["samples"], 1);
    EXPECT_EQ(s["modes"][2]["settings"]["shading"], "unlit");  // fastest moves only per-sample lighting
    // fastest renders at half resolution, which is not compared sample by sample: its counts are null, its RMSE
    // and coverage error measured; the others are compared.
    EXPECT_EQ(s["modes"][2]["settings"]["resolution_divisor"], 2);
    EXPECT_TRUE(s["modes"][2]["genuine"].is_null());
    EXPECT_TRUE(s["modes"][2]["ambiguous"].is_null());
    EXPECT_GT(s["modes"][2]["color_rmse"].get<double>(), 0.0);
    EXPECT_TRUE(s["modes"][2]["coverage_error"].is_number());
    EXPECT_TRUE(s["modes"][1]["genuine"].is_number());
    EXPECT_EQ(s["modes"][2]["samples"], 32 * 24);
    EXPECT_EQ(s["front"].size(), on_front);
    EXPECT_GE(on_front, 1u);

    const std::vector<std::string> lines = split(read_text(out / "tradeoff.csv"), '\n');
    ASSERT_EQ(lines.size(), 4u);
    const std::vector<std::string> header = split(lines[0], ',');
    EXPECT_EQ(header.front(), "scene");
    EXPECT_EQ(header.back(), "on_front");
    for (size_t i = 1; i < lines.size(); ++i) EXPECT_EQ(split(lines[i], ',').size(), header.size()) << lines[i];
    EXPECT_EQ(split(lines[2], ',')[1], "samples4");
    const std::vector<std::string> fastest = split(lines[3], ',');
    const auto column = [&](const char* name) {
        return static_cast<size_t>(std::find(header.begin(), header.end(), name) - header.begin());
    };
    ASSERT_LT(column("genuine"), header.size());
    EXPECT_EQ(fastest[column("resolution_divisor")], "2");
    EXPECT_EQ(fastest[column("genuine")], "");  // not compared
    EXPECT_EQ(split(lines[2], ',')[column("resolution_divisor")], "1");

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

// A mode named in --modes that changes nothing on a scene (half resolution where 2 does not divide the size) is
// measured, under a warning that says so.
TEST(TradeoffCli, aNamedModeThatChangesNothingOnTheSceneIsWarnedAbout) {
    TempDir dir;
    const fs::path scene = small_scene(dir, "single_triangle.yaml", 63, 48);
    const CliRun r = run_raster({"tradeoff", scene.string(), "-o", (dir / "out").string(), "--modes",
                                 "baseline,half-resolution,samples4", "--runs", "1", "--reference-grid", "2"});
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.err.find("mode half-resolution changes nothing on this scene"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("mode samples4 changes nothing"), std::string::npos) << r.err;
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

}  // namespace
}  // namespace raster::harness
