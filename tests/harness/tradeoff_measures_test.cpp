// The trade-off sweep's measures, worked out by hand: the Pareto front, the median, colour RMSE, the exact areas.
#include "harness/tradeoff/tradeoff.h"

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "raster/compat/scene_loader.h"

namespace raster::harness {
namespace {

// A scene seen by a 90-degree camera from (0, 0, 5) on a 100 x 100 image: the plane z = 0 maps to the screen by
// (x, y) -> (50 + 10 x, 50 - 10 y), so areas are easy to work out by hand.
Scene hand_scene(const std::string& vertices, const std::string& faces) {
    const std::string text =
        "image: {width: 100, height: 100}\ncamera: {eye: [0, 0, 5], target: [0, 0, 0], fov: 90}\n"
        "render: {shading: unlit}\nmeshes:\n  - vertices: " +
        vertices + "\n    faces: " + faces + "\n";
    return parse_scene(text, "hand.yaml");
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

}  // namespace
}  // namespace raster::harness
