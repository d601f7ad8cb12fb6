// The oracle's own keyframe sampling against values worked by hand, and raster's posed float model matrix within the
// oracle's bound (animation_pose.h) on seeded random node chains of every interpolation.
#include "oracle/reference/animation_pose.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>

#include <gtest/gtest.h>

#include "oracle/reference/matrix_magnitude.h"
#include "raster/transform/model_matrix.h"
#include "raster/transform/scene_pose.h"

namespace raster::oracle {
namespace {

const double kPi = 3.14159265358979323846;

TEST(OracleAnimationPose, slerpHalfwayBetweenQuarterTurnsIsTheEighthTurnTheShortWay) {
    const double h = std::sqrt(0.5);
    const glm::dvec4 identity(1, 0, 0, 0), quarter_about_y(h, 0, h, 0);
    for (const double sign : {1.0, -1.0}) {  // -q is q's rotation: the same path
        const glm::dvec4 q = oracle_slerp(identity, sign * quarter_about_y, 0.5);
        EXPECT_NEAR(q[0], std::cos(kPi / 8), 1e-15);
        EXPECT_NEAR(q[2], std::sin(kPi / 8), 1e-15);
        EXPECT_NEAR(q[1], 0.0, 1e-15);
    }
    // A third of the way along a half turn about z: a sixth of a turn.
    const glm::dvec4 third = oracle_slerp(identity, {0, 0, 0, 1}, 1.0 / 3.0);
    EXPECT_NEAR(third[0], std::cos(kPi / 6), 1e-15);
    EXPECT_NEAR(third[3], std::sin(kPi / 6), 1e-15);
    EXPECT_EQ(oracle_slerp(identity, identity, 0.7), identity);
}

TEST(OracleAnimationPose, tracksAreSampledAsDocsAnimationSays) {
    Track<glm::vec3> track;
    track.times = {1.0f, 2.0f, 4.0f};
    track.values = {{0, 0, 0}, {2, 4, 6}, {4, 0, -2}};
    EXPECT_EQ(oracle_sample(track, 0.5f).value, glm::dvec3(0, 0, 0));  // before the first key
    EXPECT_EQ(oracle_sample(track, 9.0f).value, glm::dvec3(4, 0, -2));  // after the last
    EXPECT_EQ(oracle_sample(track, 1.25f).value, glm::dvec3(0.5, 1, 1.5));
    EXPECT_EQ(oracle_sample(track, 3.0f).value, glm::dvec3(3, 2, 2));
    EXPECT_EQ(oracle_sample(track, 2.0f).bound, glm::dvec3(0.0));  // a key's own time: its value exactly
    EXPECT_GT(oracle_sample(track, 3.0f).bound.x, 0.0);
    track.interpolation = KeyInterpolation::step;
    EXPECT_EQ(oracle_sample(track, 3.9f).value, glm::dvec3(2, 4, 6));
    EXPECT_EQ(oracle_sample(track, 3.9f).bound, glm::dvec3(0.0));
    // A cubic spline over a gap of 2 halfway: v0 / 2 + gap b0 / 8 + v1 / 2 - gap a1 / 8.
    Track<glm::vec3> spline;
    spline.interpolation = KeyInterpolation::cubic_spline;
    spline.times = {0.0f, 2.0f};
    spline.values = {{9, 9, 9}, {1, 0, 0}, {0, 1, 0}, {0, 0, 4}, {3, 0, 0}, {9, 9, 9}};
    const glm::dvec3 want = 0.5 * glm::dvec3(1, 0, 0) + 0.25 * glm::dvec3(0, 1, 0) + 0.5 * glm::dvec3(3, 0, 0) -
                            0.25 * glm::dvec3(0, 0, 4);
    const SampledVector got = oracle_sample(spline, 1.0f);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(got.value[i], want[i], 1e-15);
}

glm::vec4 random_rotation(std::mt19937& random) {
    std::normal_distribution<float> normal;
    return glm::normalize(glm::vec4(normal(random), normal(random), normal(random), normal(random)));
}

template <typename T, typename Draw>
Track<T> random_track(std::mt19937& random, Draw draw) {
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    Track<T> track;
    track.interpolation = static_cast<KeyInterpolation>(std::uniform_int_distribution<int>(0, 2)(random));
    float time = 3.0f * unit(random) - 1.0f;
    for (int k = 2 + static_cast<int>(unit(random) * 4.0f); k > 0; --k) {
        track.times.push_back(time);
        time = std::nextafter(time + 0.05f + 2.0f * unit(random), INFINITY);
        for (int v = track.interpolation == KeyInterpolation::cubic_spline ? 3 : 1; v > 0; --v)
            track.values.push_back(draw());
    }
    return track;
}

// Raster's posed model matrix (pose_scene, then its float composition) against the oracle's own pose, on chains of
// one to three nodes with tracks of every interpolation, some keys close enough for raster's chord.
TEST(OracleAnimationPose, rastersPosedMatrixIsWithinTheOraclesBound) {
    std::mt19937 random(20261207);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    double worst_share = 0.0, worst_size = 0.0;
    for (int trial = 0; trial < 2000; ++trial) {
        auto animation = std::make_shared<SceneAnimation>();
        const int depth = 1 + trial % 3;
        for (int n = 0; n < depth; ++n) {
            AnimatedNode node;
            node.parent = n - 1;
            if (trial % 5 == 0) node.fixed.push_back(ScaleStep{{2.0f, 0.5f, 1.0f}});
            const float scale = 0.1f + 4.0f * unit(random);
            node.translation = random_track<glm::vec3>(random, [&] {
                return glm::vec3(unit(random) - 0.5f, unit(random) - 0.5f, unit(random) - 0.5f) * scale;
            });
            node.scale = random_track<glm::vec3>(random, [&] {
                return glm::vec3(0.5f + unit(random), 0.5f + unit(random), 0.5f + unit(random));
            });
            node.rotation = random_track<glm::vec4>(random, [&] { return random_rotation(random); });
            if (trial % 2)  // neighbouring keys a tiny turn apart
                for (size_t i = 1; i < node.rotation.values.size(); ++i)
                    node.rotation.values[i] = glm::normalize(node.rotation.values[i - 1] +
                                                             random_rotation(random) * (0.05f * unit(random)));
            animation->nodes.push_back(node);
        }
        animation->meshes.push_back({depth - 1, {RotateStep{30.0f, {0, 1, 0}}}});
        Scene scene;
        scene.meshes.emplace_back();
        scene.animation = animation;
        const float time = 6.0f * unit(random) - 1.5f;
        pose_scene(scene, time);
        ASSERT_EQ(scene.posed_at, time);
        const glm::mat4 raster = model_matrix(scene.meshes[0].transform);
        const ModelMatrixError model = posed_model_error(*animation, 0, time);
        const double size = 1.0 + largest_entry(absolute(model.exact));
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r) {
                const double error = std::fabs(double(raster[c][r]) - model.exact[c][r]);
                ASSERT_LE(error, model.bound[c][r]) << "trial " << trial << " entry [" << c << "][" << r << "]";
                if (model.bound[c][r] > 0.0) worst_share = std::max(worst_share, error / model.bound[c][r]);
                worst_size = std::max(worst_size, model.bound[c][r] / size);
            }
    }
    // The errors reach a visible share of their bounds, and the bounds stay small against the matrix, under the
    // 1/256 that OracleModel allows a static chain: no licence for another pose (normalised lerp in place of slerp
    // strays by up to 0.07 of a unit entry). The largest shares come from slerp where acos is ill-conditioned, just
    // past raster's chord switch (20u / sin(w) at w ~ 0.03), and from cubic rotations whose spline passes near zero
    // before it is normalised (2 |dH| / |H|), compounded down three nodes.
    EXPECT_GT(worst_share, 0.01);
    EXPECT_LT(worst_size, 1.0 / 256.0);
}

}  // namespace
}  // namespace raster::oracle
