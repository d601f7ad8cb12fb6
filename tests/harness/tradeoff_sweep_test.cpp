// The trade-off sweep and its outputs: more samples measure better, the mode catalogue, the report's section.
#include "harness/tradeoff/tradeoff.h"

#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "harness/tradeoff/tradeoff_modes.h"
#include "oracle/report/report.h"
#include "raster/compat/scene_loader.h"
#include "tests/support/cli_run.h"
#include "tests/support/tradeoff_test_support.h"

namespace raster::harness {
namespace {

using namespace tradeoff_test;
using test_support::CliRun;
using test_support::run_raster;

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

TEST(TradeoffMeasures, lightingOncePerTriangleHasALargerColourRmseThanPerVertexOrPerSampleAndTheOracleAgrees) {
    // The teapot at 128 x 128, Blinn-Phong: flat facets are visible at this size, Gouraud's interpolated colours much
    // less so. The oracle lights each rate its own way, so none of them is a genuine disagreement.
    TempDir dir;
    const Scene scene = load_scene(small_scene(dir, "teapot.yaml", 128, 128));
    const SceneTradeoff result =
        measure_scene(scene, named_modes({"baseline", "shading-gouraud", "shading-flat"}), quick_options());
    ASSERT_EQ(result.modes.size(), 3u);
    EXPECT_EQ(result.modes[1].settings.shading, ShadingMode::gouraud);
    EXPECT_EQ(result.modes[2].settings.shading, ShadingMode::flat);
    EXPECT_GT(result.modes[2].color_rmse, result.modes[1].color_rmse);
    EXPECT_GT(result.modes[2].color_rmse, result.modes[0].color_rmse);
    for (const ModeResult& mode : result.modes) EXPECT_EQ(mode.genuine, 0u) << mode.mode;
}

TEST(TradeoffModes, namesAreUniqueAndEachModeChangesWhatItsNameSays) {
    std::set<std::string> names;
    for (const TradeoffMode& mode : tradeoff_modes()) EXPECT_TRUE(names.insert(mode.name).second) << mode.name;
    EXPECT_EQ(find_tradeoff_mode("no-such-mode"), nullptr);
    const RenderSettings base;
    EXPECT_EQ(apply_mode(*find_tradeoff_mode("snap12"), base).snap_bits, 12);
    const RenderSettings grid = apply_mode(*find_tradeoff_mode("grid8x8"), base);
    EXPECT_EQ(grid.samples, 64);
    EXPECT_EQ(grid.pattern, SamplePattern::grid);
    EXPECT_FALSE(apply_mode(*find_tradeoff_mode("hiz-off"), base).modes.hierarchical_z);
    // Cheap settings that measure no faster are not modes (they stay render settings).
    for (const char* slower : {"snap4", "edges-float", "affine", "depth-float", "depth-fixed24", "guard-band"})
        EXPECT_EQ(find_tradeoff_mode(slower), nullptr) << slower;
    // The lighting rate moves Phong and Blinn-Phong only.
    RenderSettings phong = base;
    phong.shading = ShadingMode::phong;
    EXPECT_EQ(apply_mode(*find_tradeoff_mode("shading-gouraud"), phong).shading, ShadingMode::gouraud);
    EXPECT_EQ(apply_mode(*find_tradeoff_mode("shading-flat"), base).shading, ShadingMode::flat);
    for (ShadingMode kept : {ShadingMode::unlit, ShadingMode::cel, ShadingMode::gooch}) {
        RenderSettings other = base;
        other.shading = kept;
        EXPECT_EQ(apply_mode(*find_tradeoff_mode("shading-flat"), other).shading, kept);
        EXPECT_EQ(apply_mode(*find_tradeoff_mode("fastest"), other).shading, kept);
    }
    const RenderSettings fastest = apply_mode(*find_tradeoff_mode("fastest"), base);  // base: Blinn-Phong
    EXPECT_EQ(fastest.shading, ShadingMode::gouraud);
    EXPECT_EQ(fastest.snap_bits, 8);
    EXPECT_EQ(fastest.samples, 1);
    EXPECT_EQ(fastest.modes.edges, EdgeArithmetic::fixed);
    EXPECT_EQ(fastest.modes.interpolation, Interpolation::perspective);
    EXPECT_EQ(fastest.modes.depth, DepthFormat::reversed_z);
    EXPECT_EQ(fastest.modes.clipping, Clipping::full);
    // Half resolution where 2 divides the size (the default 640 x 480), native where it does not: a mode never
    // makes a scene invalid.
    EXPECT_EQ(fastest.resolution_divisor, 2);
    EXPECT_EQ(apply_mode(*find_tradeoff_mode("half-resolution"), base).resolution_divisor, 2);
    RenderSettings odd = base;
    odd.width = 641;
    EXPECT_EQ(apply_mode(*find_tradeoff_mode("fastest"), odd).resolution_divisor, 1);
    EXPECT_EQ(apply_mode(*find_tradeoff_mode("half-resolution"), odd).resolution_divisor, 1);
    EXPECT_EQ(apply_mode(*find_tradeoff_mode("exact"), fastest).resolution_divisor, 1);
    EXPECT_FALSE(same_mode_settings(base, apply_mode(*find_tradeoff_mode("half-resolution"), base)));
}

TEST(TradeoffModes, theDefaultSweepLeavesOutModesThatRepeatTheBaseline) {
    auto names = [](const std::vector<const TradeoffMode*>& sweep) {
        std::set<std::string> out;
        for (const TradeoffMode* mode : sweep) out.insert(mode->name);
        return out;
    };
    const std::set<std::string> defaults = names(default_sweep(RenderSettings{}));  // 8 bits, 1 sample, fixed, ...
    for (const char* kept :
         {"baseline", "snap12", "samples4", "grid8x8", "hiz-off", "fastest", "exact"})
        EXPECT_TRUE(defaults.count(kept)) << kept;
    for (const char* lighting : {"shading-gouraud", "shading-flat"}) {  // only where lighting is per sample
        EXPECT_FALSE(defaults.count(lighting)) << lighting;
        EXPECT_TRUE(names(default_sweep(RenderSettings{}, SceneFeatures{false, false, false, true})).count(lighting));
    }
    for (const char* repeat :
         {"snap8", "samples1", "edges-fixed", "perspective", "depth-reversed-z", "clip-full", "hiz-on"})
        EXPECT_FALSE(defaults.count(repeat)) << repeat;
    RenderSettings four;
    four.samples = 4;
    const std::set<std::string> with_four = names(default_sweep(four));
    EXPECT_TRUE(with_four.count("samples1"));
    EXPECT_FALSE(with_four.count("samples4"));
}

TEST(TradeoffModes, shadowModesAreSweptOnlyWhereALightCastsShadowsAndSetWhatTheyName) {
    auto has = [](const std::vector<const TradeoffMode*>& sweep, const std::string& name) {
        for (const TradeoffMode* mode : sweep)
            if (mode->name == name) return true;
        return false;
    };
    const RenderSettings base;  // 1024 texels, pcf 1
    const std::vector<const TradeoffMode*> plain = default_sweep(base);
    const std::vector<const TradeoffMode*> shadowed = default_sweep(base, SceneFeatures{false, true});
    for (const char* name : {"shadow512", "shadow2048", "shadow4096", "pcf3", "pcf5", "shadow-bias-low",
                             "shadow-bias-high"}) {
        EXPECT_FALSE(has(plain, name)) << name;
        EXPECT_TRUE(has(shadowed, name)) << name;
    }
    EXPECT_FALSE(has(shadowed, "shadow1024"));  // the default resolution: baseline already
    EXPECT_FALSE(has(shadowed, "pcf1"));
    EXPECT_EQ(apply_mode(*find_tradeoff_mode("shadow4096"), base).shadows.resolution, 4096);
    EXPECT_EQ(apply_mode(*find_tradeoff_mode("pcf5"), base).shadows.pcf, 5);
    EXPECT_EQ(apply_mode(*find_tradeoff_mode("shadow-bias-high"), base).shadows.slope_bias, 4.0f);
    EXPECT_EQ(apply_mode(*find_tradeoff_mode("fastest"), base).shadows.resolution, 512);
    EXPECT_EQ(apply_mode(*find_tradeoff_mode("exact"), base).shadows.resolution, 4096);
    // A lit scene whose light casts shadows has the feature; the same scene unlit does not.
    Scene scene;
    scene.settings.shading = ShadingMode::blinn_phong;
    scene.lights.push_back({glm::vec3(0.0f, 4.0f, 0.0f), glm::vec3(1.0f), 1.0f, false, true});
    EXPECT_TRUE(scene_features(scene).shadows);
    scene.settings.shading = ShadingMode::unlit;
    EXPECT_FALSE(scene_features(scene).shadows);
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
