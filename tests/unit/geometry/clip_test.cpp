// Homogeneous clipping: untouched inside, plane equations hold after clipping, barycentrics stay consistent.
#include "raster/geometry/clip.h"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

namespace raster {
namespace {

const ClipVolume kVolume{0.5f, 50.0f};

// Every output vertex satisfies every plane, within float rounding of the intersection.
void expect_inside(const ClippedPolygon& polygon) {
    for (int i = 0; i < polygon.count; ++i) {
        const glm::vec4& p = polygon.vertices[i].position;
        const float slack = 1e-5f * std::fabs(p.w);
        EXPECT_GE(p.w, kVolume.near);
        EXPECT_LE(p.w, kVolume.far * (1 + 1e-6f));
        EXPECT_LE(std::fabs(p.x), p.w + slack);
        EXPECT_LE(std::fabs(p.y), p.w + slack);
    }
}

// Each clipped vertex is the original triangle's point at its barycentrics.
void expect_barycentrics_reproduce(const ClippedPolygon& polygon, const glm::vec4 (&original)[3]) {
    for (int i = 0; i < polygon.count; ++i) {
        const ClipVertex& v = polygon.vertices[i];
        EXPECT_NEAR(v.bary.x + v.bary.y + v.bary.z, 1.0f, 1e-6f);
        const glm::vec4 rebuilt = v.bary.x * original[0] + v.bary.y * original[1] + v.bary.z * original[2];
        for (int k = 0; k < 4; ++k) EXPECT_NEAR(rebuilt[k], v.position[k], 1e-4f * (1 + std::fabs(rebuilt[k])));
    }
}

TEST(Clip, triangleInsideIsUntouched) {
    const glm::vec4 a(0, 0, 0.5f, 2), b(1, 0, 0.5f, 2), c(0, 1, 0.5f, 3);
    const ClippedPolygon polygon = clip_triangle(a, b, c, kVolume);
    ASSERT_EQ(polygon.count, 3);
    EXPECT_FALSE(polygon.clipped);
    EXPECT_EQ(polygon.vertices[0].position, a);
    EXPECT_EQ(polygon.vertices[2].position, c);
    EXPECT_EQ(polygon.vertices[1].bary, glm::vec3(0, 1, 0));
}

TEST(Clip, triangleOutsideOnePlaneIsRemoved) {
    EXPECT_EQ(clip_triangle({5, 0, 0, 1}, {6, 1, 0, 1}, {7, 0, 0, 2}, kVolume).count, 0);   // right of x = w
    EXPECT_EQ(clip_triangle({0, 0, 0, 0.1f}, {0.1f, 0, 0, 0.2f}, {0, 0.1f, 0, 0.3f}, kVolume).count, 0);  // before near
}

TEST(Clip, oneVertexBehindTheCameraMakesAQuad) {
    // Vertex c is behind the eye (w < 0): the near plane cuts two edges, leaving a quadrilateral with w >= near.
    // (c is outside the side planes too, as every point behind the eye is, but the near cut already removes it.)
    const glm::vec4 original[3] = {{0, 0, 0, 2}, {0.2f, 0, 0, 2}, {0, 0, 0, -3}};
    const ClippedPolygon polygon = clip_triangle(original[0], original[1], original[2], kVolume);
    ASSERT_EQ(polygon.count, 4);
    EXPECT_TRUE(polygon.clipped);
    expect_inside(polygon);
    expect_barycentrics_reproduce(polygon, original);
    int on_near = 0;
    for (int i = 0; i < polygon.count; ++i) on_near += std::fabs(polygon.vertices[i].position.w - kVolume.near) < 1e-6f;
    EXPECT_EQ(on_near, 2);
}

TEST(Clip, twoVerticesBehindTheCameraKeepATriangle) {
    const glm::vec4 original[3] = {{0, 0, 0, 4}, {0.1f, 0, 0, -1}, {0, 0.1f, 0, -2}};
    const ClippedPolygon polygon = clip_triangle(original[0], original[1], original[2], kVolume);
    ASSERT_EQ(polygon.count, 3);
    expect_inside(polygon);
    expect_barycentrics_reproduce(polygon, original);
}

TEST(Clip, hugeTriangleIsCutToTheFrustum) {
    // Crosses all four side planes; a vertex at w = 0 is also handled (never divided by).
    const glm::vec4 original[3] = {{-1000, -1000, 0, 10}, {1000, -1000, 0, 10}, {0, 1000, 0, 0}};
    const ClippedPolygon polygon = clip_triangle(original[0], original[1], original[2], kVolume);
    ASSERT_GE(polygon.count, 3);
    ASSERT_LE(polygon.count, 9);
    expect_inside(polygon);
    expect_barycentrics_reproduce(polygon, original);
}

TEST(Clip, sharedEdgeGetsBitIdenticalIntersections) {
    // Two triangles share the edge p-q, which crosses the near plane, listed in opposite directions.
    const glm::vec4 p(0.3f, 0.1f, 0, 3.7f), q(-0.2f, 0.4f, 0, -1.3f), r(1, 1, 0, 2), s(-1, -1, 0, 2.5f);
    const ClippedPolygon first = clip_triangle(p, q, r, kVolume);
    const ClippedPolygon second = clip_triangle(q, p, s, kVolume);
    auto near_points = [](const ClippedPolygon& polygon) {
        std::vector<glm::vec4> points;
        for (int i = 0; i < polygon.count; ++i)
            if (std::fabs(polygon.vertices[i].position.w - kVolume.near) < 1e-5f)
                points.push_back(polygon.vertices[i].position);
        return points;
    };
    const auto a = near_points(first), b = near_points(second);
    bool shared = false;
    for (const auto& x : a)
        for (const auto& y : b) shared = shared || x == y;
    EXPECT_TRUE(shared) << "the point where p-q meets the near plane differs between the two triangles";
}

TEST(Clip, nonFiniteInputIsRejected) {
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    EXPECT_EQ(clip_triangle({nan, 0, 0, 1}, {1, 0, 0, 1}, {0, 1, 0, 1}, kVolume).count, 0);
    EXPECT_EQ(clip_triangle({0, 0, 0, 1}, {inf, 0, 0, 1}, {0, 1, 0, 1}, kVolume).count, 0);
    EXPECT_EQ(clip_triangle({0, 0, 0, 1}, {1, 0, 0, 1}, {0, 1, 0, -inf}, kVolume).count, 0);
}

TEST(Clip, vertexExactlyOnTheNearPlaneIsKept) {
    const ClippedPolygon polygon = clip_triangle({0, 0, 0, kVolume.near}, {0.2f, 0, 0, 1}, {0, 0.2f, 0, 1}, kVolume);
    ASSERT_EQ(polygon.count, 3);
    EXPECT_FALSE(polygon.clipped);
}


// An orthographic frame (w = 1, reversed-Z depth in z): near and far are the planes z = w and z = 0, whatever the
// camera's near and far distances, and w stays 1 (never pinned to a near distance above 1).
TEST(Clip, orthographicNearAndFarArePlanesOfZAndWStaysOne) {
    const ClipVolume volume{4.0f, 9.0f, 1.0, true};
    const glm::vec4 original[3] = {{0.0f, 0.0f, 1.5f, 1.0f}, {0.5f, 0.0f, 0.5f, 1.0f}, {0.0f, 0.5f, -0.5f, 1.0f}};
    const ClippedPolygon polygon = clip_triangle(original[0], original[1], original[2], volume);
    ASSERT_EQ(polygon.count, 5);  // both planes cut a corner off
    for (int i = 0; i < polygon.count; ++i) {
        const glm::vec4& p = polygon.vertices[i].position;
        EXPECT_EQ(p.w, 1.0f);
        EXPECT_LE(p.z, 1.0f + 1e-6f);
        EXPECT_GE(p.z, -1e-6f);
    }
    expect_barycentrics_reproduce(polygon, original);
    // Entirely inside: untouched, though w = 1 is below the near distance 4.
    EXPECT_TRUE(inside_clip_volume({0.2f, 0.1f, 0.5f, 1.0f}, volume));
    EXPECT_FALSE(inside_clip_volume({0.2f, 0.1f, 1.25f, 1.0f}, volume));
    EXPECT_FALSE(inside_clip_volume({0.2f, 0.1f, -0.25f, 1.0f}, volume));
}

}  // namespace
}  // namespace raster
