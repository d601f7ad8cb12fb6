// Keyframe tracks: slerp against the geometry of rotations (the angle from each end grows and shrinks in
// proportion, the short way round, at unit length), linear and step keys, glTF's cubic spline against its Hermite
// basis worked by hand, clamping outside the keys, and a node's chain before its parent's.
#include "raster/scene/animation.h"

#include <cmath>
#include <random>
#include <variant>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

namespace raster {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The angle of the rotation taking unit quaternion a to b, in double: 2 acos |a . b|.
double rotation_angle(const glm::vec4& a, const glm::vec4& b) {
    const double d = std::fabs(glm::dot(glm::dvec4(a), glm::dvec4(b)) /
                               (glm::length(glm::dvec4(a)) * glm::length(glm::dvec4(b))));
    return 2.0 * std::acos(std::min(1.0, d));
}

glm::vec4 random_unit(std::mt19937& random) {
    std::normal_distribution<float> normal;
    return glm::normalize(glm::vec4(normal(random), normal(random), normal(random), normal(random)));
}

TEST(Animation, slerpTurnsAtAConstantRateTheShortWayRound) {
    std::mt19937 random(7);
    std::uniform_real_distribution<float> fraction(0.0f, 1.0f);
    for (int trial = 0; trial < 2000; ++trial) {
        const glm::vec4 a = random_unit(random), b = random_unit(random);
        const float t = fraction(random);
        const glm::vec4 q = slerp(a, b, t);
        const double whole = rotation_angle(a, b);  // at most pi: the short way
        ASSERT_NEAR(glm::length(q), 1.0f, 1e-5f);
        // A fraction t of the rotation from a, the rest of it to b (float: about 1e-3 radians near the ends).
        ASSERT_NEAR(rotation_angle(a, q), t * whole, 2e-3) << "trial " << trial;
        ASSERT_NEAR(rotation_angle(q, b), (1.0 - t) * whole, 2e-3) << "trial " << trial;
        // -b is b's rotation: the same path.
        const glm::vec4 r = slerp(a, -b, t);
        ASSERT_NEAR(rotation_angle(q, r), 0.0, 2e-3);
    }
}

TEST(Animation, aHalfwaySlerpBetweenQuarterTurnsIsTheEighthTurn) {
    const float h = static_cast<float>(std::sqrt(0.5));
    const glm::vec4 identity(1, 0, 0, 0), quarter_about_y(h, 0, h, 0);
    const glm::vec4 q = slerp(identity, quarter_about_y, 0.5f);
    EXPECT_NEAR(q.x, std::cos(kPi / 8), 1e-6);
    EXPECT_NEAR(q.z, std::sin(kPi / 8), 1e-6);
    // The far way round would pass through the three-eighths turn the other way: w = cos(3 pi / 8) at most.
    const glm::vec4 p = slerp(identity, -quarter_about_y, 0.5f);
    EXPECT_NEAR(std::fabs(p.x), std::cos(kPi / 8), 1e-6);
}

Track<glm::vec3> track(KeyInterpolation interpolation, std::vector<float> times, std::vector<glm::vec3> values) {
    Track<glm::vec3> out;
    out.interpolation = interpolation;
    out.times = std::move(times);
    out.values = std::move(values);
    return out;
}

TEST(Animation, linearAndStepKeysAndClampingOutsideThem) {
    const auto linear = track(KeyInterpolation::linear, {1, 3}, {{0, 0, 0}, {4, 2, -2}});
    EXPECT_EQ(sample_track(linear, 2.0f), glm::vec3(2, 1, -1));
    EXPECT_EQ(sample_track(linear, 0.0f), glm::vec3(0, 0, 0));
    EXPECT_EQ(sample_track(linear, 9.0f), glm::vec3(4, 2, -2));
    const auto step = track(KeyInterpolation::step, {1, 3}, {{0, 0, 0}, {4, 2, -2}});
    EXPECT_EQ(sample_track(step, 2.9f), glm::vec3(0, 0, 0));
    EXPECT_EQ(sample_track(step, 3.0f), glm::vec3(4, 2, -2));
    // No interval holds a NaN: the first key, never a read before it.
    EXPECT_EQ(sample_track(linear, std::nanf("")), glm::vec3(0, 0, 0));
}

TEST(Animation, aCubicSplineFollowsGltfsHermiteBasis) {
    // Keys at 0 and 2: values 0 and 1, the first key's out-tangent 1, the second's in-tangent 0.
    const auto spline = track(KeyInterpolation::cubic_spline, {0, 2},
                              {{9, 9, 9}, {0, 0, 0}, {1, 0, 0}, {0, 0, 0}, {1, 1, 1}, {9, 9, 9}});
    // At u = 1/4 (t = 0.5): (-2u^3 + 3u^2) * 1 + (u^3 - 2u^2 + u) * 2 * (1, 0, 0) = 0.15625 + (0.28125, 0, 0).
    const glm::vec3 p = sample_track(spline, 0.5f);
    EXPECT_NEAR(p.x, 0.4375f, 1e-6f);
    EXPECT_NEAR(p.y, 0.15625f, 1e-6f);
    // The keys' own values at the keys; the tangents never show as values.
    EXPECT_EQ(sample_track(spline, 0.0f), glm::vec3(0, 0, 0));
    EXPECT_EQ(sample_track(spline, 2.0f), glm::vec3(1, 1, 1));
}

TEST(Animation, aNodesChainIsItsFixedStepsThenScaleRotationTranslationThenItsParents) {
    SceneAnimation animation;
    AnimatedNode parent;
    parent.rest_translation = {5, 0, 0};
    AnimatedNode child;
    child.parent = 0;
    child.fixed = {ScaleStep{glm::vec3(2.0f)}};
    child.translation = track(KeyInterpolation::linear, {0, 1}, {{0, 0, 0}, {0, 2, 0}});
    animation.nodes = {parent, child};
    const std::vector<TransformStep> chain = node_chain_at(animation, 1, 0.5f);
    ASSERT_EQ(chain.size(), 7u);  // the child's fixed scale, S, R, T; the parent's S, R, T
    EXPECT_EQ(std::get<ScaleStep>(chain[0]).factors, glm::vec3(2.0f));
    EXPECT_EQ(std::get<TranslateStep>(chain[3]).offset, glm::vec3(0, 1, 0));
    EXPECT_EQ(std::get<TranslateStep>(chain[6]).offset, glm::vec3(5, 0, 0));
}

TEST(Animation, theSpanCoversEveryTrack) {
    SceneAnimation animation;
    AnimatedNode node;
    node.scale = track(KeyInterpolation::linear, {0.5f, 2}, {{1, 1, 1}, {2, 2, 2}});
    node.translation = track(KeyInterpolation::linear, {-1, 1}, {{0, 0, 0}, {1, 1, 1}});
    animation.nodes = {node};
    find_animation_span(animation);
    EXPECT_EQ(animation.start, -1.0f);
    EXPECT_EQ(animation.end, 2.0f);
}

}  // namespace
}  // namespace raster
