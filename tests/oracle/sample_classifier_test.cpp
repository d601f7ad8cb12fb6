// The comparator's classes and bounds: for each allowance, a sample just inside its derived bound is ambiguous
// (or agreeing) and one just outside is genuine. No bound is restated here: each is read from the precision model
// and the reference geometry, and the test checks that the class changes exactly there.
#include "oracle/compare/sample_classifier.h"

#include <cmath>

#include <gtest/gtest.h>

#include "oracle/reference/precision.h"
#include "raster/geometry/vertex_stage.h"
#include "tests/support/oracle_test_scenes.h"

namespace raster::oracle {
namespace {

using testing::camera_at_origin;
using testing::covered_by;
using testing::reference_for;
using testing::scene_with_triangles;

const SampleEntry kEmpty{};

TEST(Classify, bothEmptyOrTheSameExactHitAgree) {
    const Scene scene = scene_with_triangles({{{{-1, -1, -3}, {1, -1, -4}, {0, 1, -5}}}}, camera_at_origin(), 100, 100);
    const ReferenceGeometry reference = reference_for(scene);
    EXPECT_EQ(classify_sample(reference, {3, 3}, kEmpty, kEmpty), SampleClass::agree);
    const glm::dvec2 p(50.25, 50.75);
    EXPECT_EQ(classify_sample(reference, p, covered_by(0, reference, p), covered_by(0, reference, p)), SampleClass::agree);
    EXPECT_EQ(classify_sample(reference, p, {7, {}, 1.0f}, kEmpty), SampleClass::visibility);  // no such triangle
}

// A triangle whose left edge is vertical on screen (two vertices at the same x and depth).
class EdgeBand : public ::testing::Test {
protected:
    Scene scene = scene_with_triangles({{{{-1, -1, -3}, {-1, 1, -3}, {1, 0, -3}}}}, camera_at_origin(), 100, 100);
    ReferenceGeometry reference = reference_for(scene);
    double edge_x() const { return reference.screen_vertices(0)[0].x; }
    double radius() const { return reference.polygon(0).radius; }
};

TEST_F(EdgeBand, theRadiusIsTheSnapPlusTheFloatErrorOfTheVertices) {
    ASSERT_EQ(reference.screen_vertices(0)[0].x, reference.screen_vertices(0)[1].x);
    EXPECT_GT(radius(), snap_displacement(8));
    EXPECT_LT(radius(), snap_displacement(8) * 1.5);
}

TEST_F(EdgeBand, rasterCoveringASampleJustOutsideTheTriangle) {
    const glm::dvec2 inside_band(edge_x() - radius() * (1 - 1e-6), 50.0), outside_band(edge_x() - radius() * (1 + 1e-6), 50.0);
    EXPECT_EQ(classify_sample(reference, inside_band, covered_by(0, reference, inside_band), kEmpty), SampleClass::edge_band);
    EXPECT_EQ(classify_sample(reference, outside_band, covered_by(0, reference, outside_band), kEmpty),
              SampleClass::visibility);
}

TEST_F(EdgeBand, rasterMissingASampleJustInsideTheTriangle) {
    const glm::dvec2 inside_band(edge_x() + radius() * (1 - 1e-6), 50.0), outside_band(edge_x() + radius() * (1 + 1e-6), 50.0);
    EXPECT_EQ(classify_sample(reference, inside_band, kEmpty, covered_by(0, reference, inside_band)), SampleClass::edge_band);
    EXPECT_EQ(classify_sample(reference, outside_band, kEmpty, covered_by(0, reference, outside_band)),
              SampleClass::visibility);
}

// A floor crossing the near plane (near = 2): the near edge is the screen row where the floor's depth is 2.
class ClipBoundary : public ::testing::Test {
protected:
    Scene scene = scene_with_triangles({{{{-3, -1, 5}, {3, -1, 5}, {0, -1, -40}}}}, camera_at_origin(90.0f, 2.0f, 100.0f),
                                       200, 200);
    ReferenceGeometry reference = reference_for(scene);

    // The row where the floor's exact view depth is `depth`, on the middle column: 1/w is linear in screen y.
    double row_at_depth(double depth) const {
        const double y0 = 160, y1 = 190;
        const double a = 1.0 / reference.hit(0, {100, y0}).view_depth, b = 1.0 / reference.hit(0, {100, y1}).view_depth;
        return y0 + (1.0 / depth - a) / (b - a) * (y1 - y0);
    }
};

TEST_F(ClipBoundary, aSampleBelowTheNearEdgeIsOnTheBoundaryUntilTheSquareLeavesTheWidenedPlane) {
    // Below the near edge the floor is nearer than near. The allowance ends where even the far side of the
    // r-square (its top, y - r) is nearer than near - depth_error.
    const ReferencePolygon& polygon = reference.polygon(0);
    ASSERT_GT(polygon.depth_error, 0.0);
    const double bound = row_at_depth(reference.near() - polygon.depth_error) + polygon.radius;
    ASSERT_GT(bound, row_at_depth(reference.near()) + polygon.radius);  // beyond the edge band of the near edge
    const glm::dvec2 inside(100, bound - 1e-6), outside(100, bound + 1e-6);
    EXPECT_TRUE(on_clip_boundary(reference, 0, inside));
    EXPECT_FALSE(on_clip_boundary(reference, 0, outside));
    // raster shows the floor where the oracle (clipping exactly) shows nothing.
    EXPECT_EQ(classify_sample(reference, inside, covered_by(0, reference, inside), kEmpty), SampleClass::clip_boundary);
    EXPECT_EQ(classify_sample(reference, outside, covered_by(0, reference, outside), kEmpty), SampleClass::visibility);
}

TEST_F(ClipBoundary, aSampleAboveTheNearEdgeIsOnTheBoundaryWhileTheSquareReachesTheWidenedPlane) {
    const ReferencePolygon& polygon = reference.polygon(0);
    const double bound = row_at_depth(reference.near() + polygon.depth_error) - polygon.radius;
    const glm::dvec2 inside(100, bound + 1e-6), outside(100, bound - 1e-6);
    EXPECT_EQ(classify_sample(reference, inside, kEmpty, covered_by(0, reference, inside)), SampleClass::clip_boundary);
    EXPECT_EQ(classify_sample(reference, outside, kEmpty, covered_by(0, reference, outside)), SampleClass::visibility);
}

// Two walls facing the camera, one behind the other: the depth tie bound is the sum of their reversed-Z errors
// (a wall facing the camera has the same depth over the whole square).
TEST(DepthTie, twoSurfacesTieExactlyWhileTheirReversedZGapIsWithinTheSumOfTheirErrors) {
    const float front = -5.0f;
    auto scene_with_back_wall_at = [&](float back) {
        return scene_with_triangles({{{{-4, -4, front}, {4, -4, front}, {0, 4, front}}},
                                     {{{-4, -4, back}, {4, -4, back}, {0, 4, back}}}},
                                    camera_at_origin(), 100, 100);
    };
    const glm::dvec2 p(50.5, 50.5);
    auto back_wall_ulps = [&](int ulps) {
        float z = front;
        for (int i = 0; i < ulps; ++i) z = std::nextafter(z, -100.0f);
        return z;
    };
    auto ties = [&](int ulps) {
        const ReferenceGeometry reference = reference_for(scene_with_back_wall_at(back_wall_ulps(ulps)));
        return depth_tie(reference, 0, 1, p);
    };
    // The first number of float steps behind the front wall at which the walls no longer tie.
    int low = 0, high = 1 << 14;
    ASSERT_TRUE(ties(low));
    ASSERT_FALSE(ties(high));
    while (high - low > 1) {
        const int mid = (low + high) / 2;
        (ties(mid) ? low : high) = mid;
    }
    for (const auto& [ulps, expect_tie] : {std::pair{low, true}, std::pair{high, false}}) {
        const ReferenceGeometry reference = reference_for(scene_with_back_wall_at(back_wall_ulps(ulps)));
        const double gap = reference.hit(0, p).reversed_z - reference.hit(1, p).reversed_z;
        const double bound = reference.polygon(0).reversed_z_error + reference.polygon(1).reversed_z_error +
                             reference.embree_reversed_z_error(0, p) + reference.embree_reversed_z_error(1, p);
        EXPECT_EQ(gap <= bound, expect_tie) << ulps << " steps: gap " << gap << ", bound " << bound;
        // raster shows the back wall, the oracle the front one.
        EXPECT_EQ(classify_sample(reference, p, covered_by(1, reference, p), covered_by(0, reference, p)),
                  expect_tie ? SampleClass::depth_tie : SampleClass::visibility);
    }
    EXPECT_GT(low, 10);  // the bound is wider than a few float steps, so ties are real ties
}

// One slanted triangle; a sample inside it where raster and the oracle agree on the triangle.
class AgreementBounds : public ::testing::Test {
protected:
    Scene scene = scene_with_triangles({{{{-1, -1, -2}, {1, -1, -3}, {0, 1, -6}}}}, camera_at_origin(), 100, 100);
    ReferenceGeometry reference = reference_for(scene);
    glm::dvec2 p{50.3125, 55.5625};
    SampleEntry oracle = covered_by(0, reference, p);
    AgreementTolerance tolerance = agreement_tolerance(reference, 0, p);

    // The largest float at or above `value` whose distance from `value` (in double) is within `limit`, and the next.
    static std::pair<float, float> floats_around(float value, double limit) {
        float inside = static_cast<float>(double(value) + limit);
        while (double(inside) - double(value) > limit) inside = std::nextafter(inside, -1e30f);
        while (double(std::nextafter(inside, 1e30f)) - double(value) <= limit) inside = std::nextafter(inside, 1e30f);
        return {inside, std::nextafter(inside, 1e30f)};
    }
};

TEST_F(AgreementBounds, theToleranceIsTheSpreadOverTheSquarePlusBothRenderersRoundingPlusEmbreesError) {
    const SquareRange range = reference.range_around(0, p, reference.polygon(0).radius);
    const double rounding = 2 * barycentric_rounding(reference.polygon(0).relative_depth_error);
    const glm::dvec3 embree = reference.embree_barycentric_error(0, p);
    EXPECT_GT(embree.x, 0.0);
    EXPECT_DOUBLE_EQ(tolerance.bary.x, range.max_bary.x - range.min_bary.x + rounding + embree.x);
    EXPECT_GT(tolerance.bary.x, rounding);  // a slanted triangle has a real spread
    EXPECT_LT(tolerance.bary.x, 1e-3);
}

TEST_F(AgreementBounds, barycentricsJustWithinTheirBoundAgreeAndJustBeyondAreGenuine) {
    for (int k = 0; k < 3; ++k) {
        const auto [inside, outside] = floats_around(oracle.bary[k], tolerance.bary[k]);
        SampleEntry raster = oracle;
        raster.bary[k] = inside;
        EXPECT_EQ(classify_sample(reference, p, raster, oracle), SampleClass::agree) << k;
        raster.bary[k] = outside;
        EXPECT_EQ(classify_sample(reference, p, raster, oracle), SampleClass::barycentrics) << k;
    }
}

TEST_F(AgreementBounds, viewDepthJustWithinItsBoundAgreesAndJustBeyondIsGenuine) {
    const auto [inside, outside] = floats_around(oracle.view_depth, tolerance.view_depth);
    SampleEntry raster = oracle;
    raster.view_depth = inside;
    EXPECT_EQ(classify_sample(reference, p, raster, oracle), SampleClass::agree);
    raster.view_depth = outside;
    EXPECT_EQ(classify_sample(reference, p, raster, oracle), SampleClass::depth);
}

// With culling on, a triangle seen almost edge-on may be kept by one renderer and culled by the other: where it is
// involved, a disagreement is FACING. A clearly front-facing triangle has no such allowance.
TEST(Facing, aDisagreementOverATriangleTooCloseToEdgeOnIsAmbiguousOnlyWhileItsFacingIsUncertain) {
    // The plane y = z / 3 contains the eye; tilting the third vertex by `tilt` turns it towards the eye.
    auto tilted = [](float tilt) {
        Scene scene = scene_with_triangles({{{{-1, -1, -3}, {1, -1, -3}, {0, -5.0f / 3.0f + tilt, -5}}}},
                                           camera_at_origin(), 200, 200);
        scene.settings.cull_backfaces = true;
        return scene;
    };
    const Scene grazing = tilted(1e-6f), facing = tilted(1.0f);
    const ReferenceGeometry uncertain = reference_for(grazing), certain = reference_for(facing);
    ASSERT_TRUE(uncertain.polygon(0).facing_uncertain);
    ASSERT_FALSE(certain.polygon(0).facing_uncertain);
    for (const ReferenceGeometry* reference : {&uncertain, &certain}) {
        // The centroid of the screen polygon, where the oracle (which kept it) sees the triangle and raster does not.
        glm::dvec2 centroid(0.0);
        for (const glm::dvec2& v : reference->screen_vertices(0)) centroid += v / 3.0;
        const SampleEntry oracle = covered_by(0, *reference, centroid);
        ASSERT_EQ(reference == &uncertain, reference->boundary_distance(0, centroid) < reference->polygon(0).radius);
        EXPECT_EQ(classify_sample(*reference, centroid, kEmpty, oracle),
                  reference == &uncertain ? SampleClass::facing : SampleClass::visibility);
    }
}

TEST(SampleClasses, namesAndGroups) {
    EXPECT_STREQ(to_string(SampleClass::edge_band), "edge_band");
    EXPECT_STREQ(to_string(SampleClass::depth), "depth");
    EXPECT_TRUE(is_ambiguous(SampleClass::clip_boundary));
    EXPECT_TRUE(is_ambiguous(SampleClass::facing));
    EXPECT_FALSE(is_ambiguous(SampleClass::visibility));
    EXPECT_TRUE(is_genuine(SampleClass::depth));
    EXPECT_FALSE(is_genuine(SampleClass::agree));
}

}  // namespace
}  // namespace raster::oracle
