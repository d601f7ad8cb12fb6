// Matrices send known points to known places: model transforms, look-at, reversed-Z projection, viewport.
#include "raster/transform/transform.h"

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <gtest/gtest.h>

namespace raster {
namespace {

glm::vec3 apply(const glm::mat4& m, const glm::vec3& p) {
    const glm::vec4 r = m * glm::vec4(p, 1.0f);
    return glm::vec3(r) / r.w;
}

void expect_near(const glm::vec3& actual, const glm::vec3& expected, float tolerance = 1e-5f) {
    EXPECT_NEAR(actual.x, expected.x, tolerance);
    EXPECT_NEAR(actual.y, expected.y, tolerance);
    EXPECT_NEAR(actual.z, expected.z, tolerance);
}

TEST(Transform, translateMovesPointsNotDirections) {
    const glm::mat4 m = translate_matrix({1, 2, 3});
    expect_near(apply(m, {1, 1, 1}), {2, 3, 4});
    const glm::vec4 direction = m * glm::vec4(1, 0, 0, 0);
    EXPECT_EQ(direction, glm::vec4(1, 0, 0, 0));
}

TEST(Transform, scaleScalesEachAxis) { expect_near(apply(scale_matrix({2, 3, -1}), {1, 1, 1}), {2, 3, -1}); }

TEST(Transform, rotateNinetyAboutZSendsXToY) {
    expect_near(apply(rotate_matrix(90, {0, 0, 1}), {1, 0, 0}), {0, 1, 0});
    expect_near(apply(rotate_matrix(90, {0, 0, 5}), {0, 1, 0}), {-1, 0, 0});  // axis length does not matter
    expect_near(apply(rotate_matrix(90, {1, 0, 0}), {0, 1, 0}), {0, 0, 1});  // right-handed about x
    expect_near(apply(rotate_matrix(120, {1, 1, 1}), {1, 0, 0}), {0, 1, 0});  // cycles the axes
}

TEST(Transform, quaternionMatchesTheSameRotation) {
    // (w, x, y, z) = (cos 45deg, 0, 0, sin 45deg) is 90 degrees about z; scaling the quaternion changes nothing.
    const float h = std::sqrt(0.5f);
    expect_near(apply(quaternion_matrix(h, 0, 0, h), {1, 0, 0}), {0, 1, 0});
    expect_near(apply(quaternion_matrix(3 * h, 0, 0, 3 * h), {0, 1, 0}), {-1, 0, 0});
}

TEST(Transform, lookAtPutsEyeAtOriginAndTargetOnNegativeZ) {
    const glm::vec3 eye(3, 4, 5), target(-1, 0, 2), up(0, 1, 0);
    const glm::mat4 view = look_at_matrix(eye, target, up);
    expect_near(apply(view, eye), {0, 0, 0});
    const float distance = glm::length(target - eye);
    expect_near(apply(view, target), {0, 0, -distance}, 1e-4f);
    EXPECT_NEAR(glm::determinant(glm::mat3(view)), 1.0f, 1e-5f);
    // A point above the eye (along world up) lands at positive view y.
    EXPECT_GT(apply(view, eye + glm::vec3(0, 1, 0)).y, 0.0f);
}

TEST(Transform, lookAtModelMatrixIsTheInverseOfTheView) {
    const glm::vec3 eye(1, 2, 3), target(0, 0, 0), up(0, 1, 0);
    const glm::mat4 product = look_at_matrix(eye, target, up) * look_at_model_matrix(eye, target, up);
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) EXPECT_NEAR(product[c][r], c == r ? 1.0f : 0.0f, 1e-5f);
}

TEST(Transform, perspectiveMapsNearToOneAndFarToZero) {
    const float near = 0.5f, far = 40.0f;
    const glm::mat4 p = perspective_matrix(60, 2.0f, near, far);
    EXPECT_NEAR(apply(p, {0, 0, -near}).z, 1.0f, 1e-6f);
    EXPECT_NEAR(apply(p, {0, 0, -far}).z, 0.0f, 1e-6f);
    // w is the view depth.
    EXPECT_FLOAT_EQ((p * glm::vec4(0, 0, -7, 1)).w, 7.0f);
    // The top of the field of view at depth d is y = d tan(30deg) and maps to NDC y = 1; the right edge has aspect 2.
    const float d = 10.0f, top = d * std::tan(30.0f * float(M_PI) / 180.0f);
    EXPECT_NEAR(apply(p, {0, top, -d}).y, 1.0f, 1e-5f);
    EXPECT_NEAR(apply(p, {2 * top, 0, -d}).x, 1.0f, 1e-5f);
}

TEST(Transform, reversedZKeepsExtremeRangesOrdered) {
    // near = 1e-6, far = 1e9: distinct distances must keep distinct, ordered depths.
    const glm::mat4 p = perspective_matrix(45, 1.0f, 1e-6f, 1e9f);
    float previous = 2.0f;
    for (float distance : {1e-6f, 1e-3f, 1.0f, 1e3f, 1e6f, 1e8f, 9e8f}) {
        const float depth = apply(p, {0, 0, -distance}).z;
        EXPECT_LT(depth, previous) << "distance " << distance;
        previous = depth;
    }
}

TEST(Transform, orthographicMapsItsBoxToTheCubeWithWOne) {
    // 4 high, aspect 2 (8 wide), near 1, far 5: (4, -2, -1) is the near plane's lower right corner.
    const glm::mat4 m = orthographic_matrix(4.0f, 2.0f, 1.0f, 5.0f);
    const glm::vec4 corner = m * glm::vec4(4.0f, -2.0f, -1.0f, 1.0f);
    EXPECT_FLOAT_EQ(corner.x, 1.0f);
    EXPECT_FLOAT_EQ(corner.y, -1.0f);
    EXPECT_FLOAT_EQ(corner.z, 1.0f);  // reversed-Z: 1 at near
    EXPECT_EQ(corner.w, 1.0f);
    const glm::vec4 far = m * glm::vec4(-2.0f, 1.0f, -5.0f, 1.0f);
    EXPECT_FLOAT_EQ(far.x, -0.5f);
    EXPECT_FLOAT_EQ(far.y, 0.5f);
    EXPECT_NEAR(far.z, 0.0f, 1e-7f);  // 0 at far
    EXPECT_EQ(far.w, 1.0f);
    // Depth is linear in view depth: halfway from near to far is 0.5.
    EXPECT_FLOAT_EQ((m * glm::vec4(0.0f, 0.0f, -3.0f, 1.0f)).z, 0.5f);
}

TEST(Transform, viewportMapsNdcCornersToScreenCorners) {
    const glm::mat4 v = viewport_matrix(640, 480);
    expect_near(apply(v, {-1, 1, 0}), {0, 0, 0});
    expect_near(apply(v, {1, -1, 0}), {640, 480, 0});
    expect_near(apply(v, {0, 0, 0.25f}), {320, 240, 0.25f});
}

TEST(Transform, normalMatrixKeepsNormalsPerpendicular) {
    // Non-uniform scale: a plane's normal transformed by the model matrix itself would no longer be perpendicular.
    const glm::mat4 model = rotate_matrix(30, {0, 0, 1}) * scale_matrix({4, 1, 1});
    const glm::vec3 tangent = glm::normalize(glm::vec3(1, -1, 0)), normal = glm::normalize(glm::vec3(1, 1, 0));
    const glm::vec3 t = glm::mat3(model) * tangent;
    EXPECT_NEAR(glm::dot(t, normal_matrix(model) * normal), 0.0f, 1e-5f);
    EXPECT_GT(std::fabs(glm::dot(t, glm::mat3(model) * normal)), 0.5f);  // the wrong way really is wrong here
}

}  // namespace
}  // namespace raster
