// The exact reference geometry: max-norm distances, exact clipping with edge kinds, exact hits and square ranges.
#include "oracle/reference/reference_geometry.h"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "oracle/reference/precision.h"
#include "raster/geometry/camera_rays.h"
#include "raster/frame/render.h"
#include "raster/geometry/vertex_stage.h"
#include "raster/compat/scene_loader.h"
#include "tests/support/oracle_test_scenes.h"

namespace raster::oracle {
namespace {

using testing::camera_at_origin;
using testing::reference_for;
using testing::scene_with_triangles;

TEST(ReferenceGeometry, maxNormDistanceToASegment) {
    const glm::dvec2 a(0, 0), b(4, 0);
    EXPECT_DOUBLE_EQ(max_norm_distance_to_segment({2, 1.5}, a, b), 1.5);       // above the middle
    EXPECT_DOUBLE_EQ(max_norm_distance_to_segment({6, 1}, a, b), 2.0);         // beyond the end: max(2, 1)
    EXPECT_DOUBLE_EQ(max_norm_distance_to_segment({1, 0}, {0, 0}, {1, 1}), 0.5);  // a diagonal: at t = 1/2
    EXPECT_DOUBLE_EQ(max_norm_distance_to_segment({3, 3}, {3, 3}, {3, 3}), 0.0);  // a point
    // Against dense sampling of the segment.
    std::mt19937 random(7);
    std::uniform_real_distribution<double> coordinate(-3, 3);
    for (int trial = 0; trial < 200; ++trial) {
        const glm::dvec2 p(coordinate(random), coordinate(random)), s(coordinate(random), coordinate(random)),
            e(coordinate(random), coordinate(random));
        double sampled = 1e300;
        for (int i = 0; i <= 20000; ++i) {
            const glm::dvec2 q = s + (e - s) * (i / 20000.0);
            sampled = std::min(sampled, std::max(std::fabs(q.x - p.x), std::fabs(q.y - p.y)));
        }
        const double exact = max_norm_distance_to_segment(p, s, e);
        EXPECT_LE(exact, sampled + 1e-12);
        EXPECT_NEAR(exact, sampled, 1e-3);
    }
}

TEST(ReferenceGeometry, aTriangleInsideTheViewKeepsItsThreeEdgesAndProjectsLikeRastersVertexStage) {
    const Scene scene = scene_with_triangles({{{{-1, -1, -3}, {1, -1, -3}, {0, 1, -4}}}}, camera_at_origin(), 200, 100);
    const ReferenceGeometry reference = reference_for(scene);
    ASSERT_EQ(reference.polygon(0).count, 3u);
    const TransformedScene geometry = run_vertex_stage(scene, {});
    for (uint32_t k = 0; k < 3; ++k) {
        EXPECT_EQ(reference.edge_kind(0, k), EdgeKind::triangle);
        const glm::vec4 c = geometry.clip[k];
        const glm::dvec2 expected = screen_from_ndc(c.x / c.w, c.y / c.w, 200, 100);
        EXPECT_NEAR(reference.screen_vertices(0)[k].x, expected.x, 1e-3);
        EXPECT_NEAR(reference.screen_vertices(0)[k].y, expected.y, 1e-3);
        // The exact hit at a vertex is that vertex.
        const ExactHit hit = reference.hit(0, reference.screen_vertices(0)[k]);
        ASSERT_TRUE(hit.valid);
        EXPECT_NEAR(hit.bary[k], 1.0, 1e-9);
        EXPECT_NEAR(hit.view_depth, k == 2 ? 4.0 : 3.0, 1e-9);
    }
    // The radius: the snap plus a float error far below it for a plain scene.
    EXPECT_GT(reference.polygon(0).radius, snap_displacement(8));
    EXPECT_LT(reference.polygon(0).radius, 2 * snap_displacement(8));
}

TEST(ReferenceGeometry, aTriangleCrossingTheNearPlaneIsClippedThereAndTheEdgeIsTagged) {
    Scene scene = scene_with_triangles({{{{-3, -1, 5}, {3, -1, 5}, {0, -1, -40}}}}, camera_at_origin(90.0f, 2.0f, 100.0f),
                                       200, 200);
    const ReferenceGeometry reference = reference_for(scene);
    const ReferencePolygon& polygon = reference.polygon(0);
    ASSERT_GE(polygon.count, 3u);
    int near_edges = 0;
    for (uint32_t k = 0; k < polygon.count; ++k) {
        near_edges += reference.edge_kind(0, k) == EdgeKind::near;
        const ExactHit hit = reference.hit(0, reference.screen_vertices(0)[k]);
        ASSERT_TRUE(hit.valid);
        EXPECT_GE(hit.view_depth, 2.0 - 1e-9);  // nothing of it is nearer than the near plane
    }
    EXPECT_EQ(near_edges, 1);
    EXPECT_GT(polygon.depth_error, 0.0);
}

TEST(ReferenceGeometry, aTriangleBehindTheEyeIsEmpty) {
    const Scene scene = scene_with_triangles({{{{-1, -1, 3}, {1, -1, 3}, {0, 1, 3}}}}, camera_at_origin(), 50, 50);
    const ReferenceGeometry reference = reference_for(scene);
    EXPECT_EQ(reference.polygon(0).count, 0u);
    EXPECT_FALSE(reference.contains(0, {25, 25}));
    EXPECT_TRUE(std::isinf(reference.boundary_distance(0, {25, 25})));
}

TEST(ReferenceGeometry, aTriangleWithAVertexAtTheEyeHasNoBoundedRadius) {
    // One vertex exactly at the eye, the others behind it: exactly, nothing is in front of the near plane; but float
    // error (the eye is off the origin, so the view transform rounds) can move that vertex just in front of it,
    // where it projects anywhere. The differential fuzzer found Embree doing so.
    Camera camera = camera_at_origin(45, 1e-6f);
    camera.eye = {2, 3, 4};
    camera.target = {2, 3, -1};
    const Scene at_eye = scene_with_triangles({{{{2, 3, 4}, {3, 2, 9}, {1, 2, 9}}}}, camera, 32, 32);
    const ReferenceGeometry reference = reference_for(at_eye);
    EXPECT_EQ(reference.polygon(0).count, 0u);
    EXPECT_TRUE(std::isinf(reference.polygon(0).radius));
    // Moved clearly behind the eye (beyond its float error), the vertex bounds nothing.
    const Scene behind = scene_with_triangles({{{{2, 3, 5}, {3, 2, 9}, {1, 2, 9}}}}, camera, 32, 32);
    EXPECT_FALSE(std::isinf(reference_for(behind).polygon(0).radius));
}

TEST(ReferenceGeometry, aTriangleWithAnEdgeThroughTheEyeHasNoBoundedRadiusWhenTheNearPlaneIsThatClose) {
    // The triangle lies in the plane x = -2 z of view space, through the eye and outside the 45-degree view, and
    // its edge from view (10, 0, -5) to (-10, 0, 5) passes through the eye: exactly, it is seen edge-on and
    // touches the view volume only at the eye, so clipping leaves nothing; in float its plane misses the eye by
    // about its vertices' error, and then it covers any sample at a depth of that order. The differential fuzzer
    // found Embree hitting such a triangle at depth 9e-9.
    Camera camera = camera_at_origin(45, 1e-12f);
    camera.eye = {2, 3, 4};
    camera.target = {2, 3, -1};
    const testing::Triangle through_eye = {{{12, 3, -1}, {-8, 3, 9}, {12, 4, -1}}};
    const ReferenceGeometry reference = reference_for(scene_with_triangles({through_eye}, camera, 32, 32));
    EXPECT_EQ(reference.polygon(0).count, 0u);
    EXPECT_TRUE(std::isinf(reference.polygon(0).radius));
    // Moved off the eye by far more than the float error, the triangle has its ordinary radius.
    testing::Triangle beside = through_eye;
    for (glm::vec3& v : beside) v.x += 0.01f;
    EXPECT_FALSE(std::isinf(reference_for(scene_with_triangles({beside}, camera, 32, 32)).polygon(0).radius));
    // With the near plane well beyond the error, both renderers cut the eye's surroundings away.
    Camera far_near = camera;
    far_near.near = 0.1f;
    EXPECT_FALSE(std::isinf(reference_for(scene_with_triangles({through_eye}, far_near, 32, 32)).polygon(0).radius));
}

TEST(ReferenceGeometry, squareRangesHoldTheValuesInsideTheSquare) {
    const Scene scene = scene_with_triangles({{{{-1, -1, -2}, {1, -1, -3}, {0, 1, -6}}}}, camera_at_origin(), 100, 100);
    const ReferenceGeometry reference = reference_for(scene);
    const glm::dvec2 centre(50.3, 55.1);
    const double half = 0.75;
    const SquareRange range = reference.range_around(0, centre, half);
    ASSERT_TRUE(range.bounded);
    for (double dx = -half; dx <= half; dx += half / 8)
        for (double dy = -half; dy <= half; dy += half / 8) {
            const ExactHit hit = reference.hit(0, centre + glm::dvec2(dx, dy));
            EXPECT_GE(hit.view_depth, range.min_view_depth - 1e-12);
            EXPECT_LE(hit.view_depth, range.max_view_depth + 1e-12);
            EXPECT_GE(hit.reversed_z, range.min_reversed_z - 1e-12);
            EXPECT_LE(hit.reversed_z, range.max_reversed_z + 1e-12);
            for (int k = 0; k < 3; ++k) {
                EXPECT_GE(hit.bary[k], range.min_bary[k] - 1e-12);
                EXPECT_LE(hit.bary[k], range.max_bary[k] + 1e-12);
            }
        }
    EXPECT_GT(range.max_view_depth, range.min_view_depth);
}

TEST(ReferenceGeometry, aSquareWhereTheRayGrazesThePlaneIsUnbounded) {
    // A floor seen towards its horizon: the square around the horizon row has rays parallel to the plane.
    const Scene scene = scene_with_triangles({{{{-50, -1, 0}, {50, -1, 0}, {0, -1, -1e6f}}}},
                                             camera_at_origin(90.0f, 0.1f, 1e7f), 100, 100);
    const ReferenceGeometry reference = reference_for(scene);
    EXPECT_FALSE(reference.range_around(0, {50, 50}, 0.5).bounded);  // the horizon is the middle row
    EXPECT_TRUE(reference.range_around(0, {50, 90}, 0.5).bounded);
}

// A triangle with an edge through the viewport's corner: exact clipping leaves two vertices at the corner a few
// 1e-15 px apart, an edge whose direction is rounding noise. Read as a polygon (no edge has the point on its outer
// side), a sample 2.3 px inside the triangle came out as outside, which excused genuine disagreements there as an
// edge band or a depth tie (the differential fuzzer's finding). contains() now decides from the exact ray hit.
TEST(ReferenceGeometry, containsDecidesFromTheExactHitNotFromAClippedPolygonsRoundingNoise) {
    const testing::Triangle triangle = {{{0x1.0958d4p+0f, 0x1.0958d4p+0f, -0x1.0958d4p+0f},
                                         {0x1.4566p+0f, 0x1.831accp+2f, -0x1.d4744cp+1f},
                                         {-0x1.27bb68p+1f, 0x1.e9f3p-3f, -0x1.684c38p+0f}}};
    const Scene scene = scene_with_triangles({triangle}, camera_at_origin(90.0f, 0.1f, 100.0f), 32, 32);
    const ReferenceGeometry reference = reference_for(scene);
    const std::span<const glm::dvec2> polygon = reference.screen_vertices(0);
    bool near_duplicate = false;
    for (size_t i = 0; i < polygon.size(); ++i)
        near_duplicate |= glm::length(polygon[(i + 1) % polygon.size()] - polygon[i]) < 1e-9;
    ASSERT_TRUE(near_duplicate) << "the case needs an edge of rounding noise";
    const glm::dvec2 sample(9.5, 2.5);
    // The polygon reading: some edge puts the sample strictly outside, though it is 2.3 px from every edge.
    bool positive = false, negative = false;
    for (size_t i = 0; i < polygon.size(); ++i) {
        const glm::dvec2 edge = polygon[(i + 1) % polygon.size()] - polygon[i], to = sample - polygon[i];
        const double side = edge.x * to.y - edge.y * to.x;
        positive |= side > 0.0;
        negative |= side < 0.0;
    }
    EXPECT_TRUE(positive && negative) << "the polygon reading no longer shows the flaw";
    EXPECT_GT(reference.boundary_distance(0, sample), 2.0);
    EXPECT_TRUE(reference.contains(0, sample));
    // raster, with its exact integer coverage, covers the sample too.
    RenderOptions options;
    const RenderResult raster = render(scene, options);
    EXPECT_EQ(raster.visibility.triangle[raster.visibility.index(9, 2, 0)], 0u);
}

// The differential fuzzer's scene: a triangle whose vertices lie on a line through the eye, seen exactly end-on. Its
// double view-space normal is rounding noise, which made the exact hit land anywhere on the screen (and contains()
// say yes far from the one ray that meets it). Within the plane noise there is no exact hit; a triangle facing the
// same camera, large enough to fill its 179.5-degree field of view, keeps a hit at every pixel.
TEST(ReferenceGeometry, aTriangleSeenEndOnHasNoExactHitWhereItsPlaneIsRoundingNoise) {
    Camera camera;
    camera.eye = glm::vec3(10.0f);
    camera.target = glm::vec3(0.0f);
    camera.up = glm::vec3(1.0f, -0.9375f, 1.0f);
    camera.fov_y_degrees = 179.5f;
    camera.near = 1e-6f;
    camera.far = 1e9f;
    const glm::vec3 on_the_line[3] = {{10, 10, 9.98046875f}, {10, 10, -6.71875f}, {10, 10, -10}};
    const Scene end_on = scene_with_triangles({{on_the_line[0], on_the_line[1], on_the_line[2]}}, camera, 16, 16);
    const ReferenceGeometry degenerate = reference_for(end_on);
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x) {
            EXPECT_FALSE(degenerate.hit(0, {x + 0.5, y + 0.5}).valid) << "pixel " << x << ", " << y;
            EXPECT_FALSE(degenerate.contains(0, {x + 0.5, y + 0.5})) << "pixel " << x << ", " << y;
        }
    const Scene facing =
        scene_with_triangles({{glm::vec3(4e4f, -2e4f, -2e4f), glm::vec3(-2e4f, 4e4f, -2e4f), glm::vec3(-2e4f, -2e4f, 4e4f)}},
                             camera, 16, 16);
    const ReferenceGeometry proper = reference_for(facing);
    int hits = 0;
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x) hits += proper.contains(0, {x + 0.5, y + 0.5});
    EXPECT_EQ(hits, 16 * 16);
}

}  // namespace
}  // namespace raster::oracle
