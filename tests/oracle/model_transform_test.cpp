// The oracle's model matrix against hand-derived points, and raster's float matrix, world positions and normals
// within the bounds of model_precision.h and shading_precision.h on seeded random chains of every step kind.
#include "oracle/reference/model_precision.h"
#include "oracle/reference/model_transform.h"

#include <algorithm>
#include <cmath>
#include <random>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <gtest/gtest.h>

#include "oracle/reference/matrix_magnitude.h"
#include "oracle/reference/shading_precision.h"
#include "raster/transform/model_matrix.h"
#include "raster/transform/transform.h"

namespace raster::oracle {
namespace {

glm::dvec3 apply(const ModelTransform& transform, const glm::dvec3& p) {
    return glm::dvec3(oracle_model_matrix(transform) * glm::dvec4(p, 1.0));
}

void expect_point(const glm::dvec3& got, const glm::dvec3& want) {
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(got[i], want[i], 1e-12) << "component " << i;
}

TEST(OracleModel, aRotationTurnsCounterClockwiseSeenFromTheAxisTip) {
    expect_point(apply({{RotateStep{90.0f, {0, 0, 1}}}, {}}, {1, 0, 0}), {0, 1, 0});
    expect_point(apply({{RotateStep{90.0f, {0, 0, 5}}}, {}}, {0, 1, 0}), {-1, 0, 0});  // any non-zero length
    expect_point(apply({{RotateStep{90.0f, {0, 1, 0}}}, {}}, {0, 0, 1}), {1, 0, 0});
    expect_point(apply({{RotateStep{-630.0f, {1, 0, 0}}}, {}}, {0, 1, 0}), {0, 0, 1});  // -630 = +90
    // 120 degrees about (1, 1, 1) cycles the axes.
    expect_point(apply({{RotateStep{120.0f, {1, 1, 1}}}, {}}, {1, 0, 0}), {0, 1, 0});
}

TEST(OracleModel, aQuaternionIsNormalisedAndRotatesAsItsAxisAndHalfAngleSay) {
    expect_point(apply({{QuaternionStep{{2, 0, 0, 0}}}, {}}, {1, 2, 3}), {1, 2, 3});
    const float h = std::sqrt(0.5f);
    expect_point(apply({{QuaternionStep{{3 * h, 3 * h, 0, 0}}}, {}}, {0, 1, 0}), {0, 0, 1});  // 90 about x
}

TEST(OracleModel, aLookAtPutsTheOriginAtTheEyeWithMinusZTowardsTheTarget) {
    const ModelTransform look{{LookAtStep{{1, 0, 0}, {0, 0, 0}, {0, 1, 0}}}, {}};
    expect_point(apply(look, {0, 0, 0}), {1, 0, 0});
    expect_point(apply(look, {0, 0, -1}), {0, 0, 0});
    expect_point(apply(look, {0, 1, 0}), {1, 1, 0});
    expect_point(apply(look, {1, 0, 0}), {1, 0, -1});
}

TEST(OracleModel, stepsApplyToTheObjectFirstToLastAndTheInverseChainFollows) {
    ModelTransform chain{{ScaleStep{{2, 2, 2}}, RotateStep{90.0f, {0, 0, 1}}, TranslateStep{{0, 0, 5}}}, {}};
    expect_point(apply(chain, {1, 0, 0}), {0, 2, 5});
    // A camera at (0, 0, 5) turned 90 degrees about y: the point (0, 2, 5) is 2 up and at its origin; the camera's
    // -z looks along world -x, so world (-3, 2, 5) is 3 in front of it.
    chain.then_inverse_of = {RotateStep{90.0f, {0, 1, 0}}, TranslateStep{{0, 0, 5}}};
    expect_point(apply(chain, {1, 0, 0}), {0, 2, 0});
    chain.steps = {TranslateStep{{-3, 2, 5}}};
    expect_point(apply(chain, {0, 0, 0}), {0, 2, -3});
    MatrixStep shear;
    shear.matrix[1][0] = 1.0f;  // x += y
    expect_point(apply({{shear}, {}}, {1, 2, 0}), {3, 2, 0});
}

// A random step of each kind, with values from unit-sized to large.
TransformStep random_step(std::mt19937& random, int kind) {
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f), angle(-720.0f, 720.0f), exponent(-2.0f, 2.0f);
    auto vector = [&](float scale) { return glm::vec3(unit(random), unit(random), unit(random)) * scale; };
    switch (kind) {
        case 0: return TranslateStep{vector(std::pow(10.0f, 2.0f * exponent(random)))};
        case 1: {
            const glm::vec3 v = vector(1.0f);
            return ScaleStep{glm::sign(v) * glm::pow(glm::vec3(10.0f), vector(1.5f))};
        }
        case 2: return RotateStep{angle(random), vector(1.0f) + glm::vec3(0.0f, 0.0f, 1e-3f)};
        case 3: return QuaternionStep{{unit(random), unit(random), unit(random), unit(random) + 1e-3f}};
        case 4: {
            const glm::vec3 eye = vector(10.0f);
            return LookAtStep{eye, eye + vector(1.0f) + glm::vec3(0.0f, 0.0f, 2.0f), vector(0.3f) + glm::vec3(0, 1, 0)};
        }
        default: {
            MatrixStep m;
            for (int c = 0; c < 4; ++c)
                for (int r = 0; r < 3; ++r) m.matrix[c][r] = unit(random) * (c == r ? 3.0f : 1.0f);
            return m;
        }
    }
}

TEST(OracleModel, rastersFloatMatrixWorldPositionsAndNormalsAreWithinTheirBounds) {
    std::mt19937 random(20261206);
    std::uniform_int_distribution<int> kind(0, 5), length(1, 6);
    double worst_share = 0.0;  // the largest error seen, as a share of its bound
    double worst_chain = 0.0, worst_inverse = 0.0;
    for (int trial = 0; trial < 3000; ++trial) {
        ModelTransform transform;
        for (int i = length(random); i > 0; --i) transform.steps.push_back(random_step(random, kind(random)));
        if (trial % 3 == 0)  // seed 001's camera chain: rotations, translations and look-ats
            for (int i = length(random) / 2 + 1; i > 0; --i)
                transform.then_inverse_of.push_back(random_step(random, std::array{0, 2, 3, 4}[kind(random) % 4]));
        const ModelMatrixError model = raster_model_error(transform);
        const glm::mat4 raster = model_matrix(transform);
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r) {
                const double error = std::fabs(double(raster[c][r]) - model.exact[c][r]);
                ASSERT_LE(error, model.bound[c][r]) << "trial " << trial << " entry [" << c << "][" << r << "]";
                if (model.bound[c][r] > 0.0) worst_share = std::max(worst_share, error / model.bound[c][r]);
                const double share = model.bound[c][r] / (1.0 + largest_entry(raster_model_magnitude(model)));
                (transform.then_inverse_of.empty() ? worst_chain : worst_inverse) =
                    std::max(transform.then_inverse_of.empty() ? worst_chain : worst_inverse, share);
            }
        const glm::vec3 p(1.5f, -0.25f, 3.0f);
        const glm::dvec3 world = glm::dvec3(model.exact * glm::dvec4(glm::dvec3(p), 1.0));
        const glm::dvec3 world_error = raster_world_position_error(model, p);
        const glm::vec3 raster_world = glm::vec3(raster * glm::vec4(p, 1.0f));
        for (int i = 0; i < 3; ++i) ASSERT_LE(std::fabs(double(raster_world[i]) - world[i]), world_error[i]) << trial;
        const glm::vec3 n = glm::normalize(glm::vec3(0.3f, -0.8f, 0.5f));
        const glm::dvec3 normal =
            glm::normalize(glm::transpose(glm::inverse(glm::dmat3(model.exact))) * glm::dvec3(n));
        const glm::vec3 raster_normal = glm::normalize(normal_matrix(raster) * n);
        ASSERT_LE(glm::length(glm::dvec3(raster_normal) - normal), raster_file_normal_error(raster_normal_matrix_error(model), n)) << trial;
    }
    // The errors reach a visible share of their bounds: the bounds follow raster's arithmetic.
    EXPECT_GT(worst_share, 0.01);
    // And the bounds stay rounding-sized against the matrix (a chain of large and small scales and long
    // translations cancels, hence the share of 1/256 rather than a few u): never a licence for another matrix.
    EXPECT_LT(worst_chain, 1.0 / 256.0);
    EXPECT_LT(worst_inverse, 1.0 / 256.0);
}

TEST(OracleModel, anUnboundedStepLeavesTheMatrixUncertainRatherThanWrong) {
    // An up vector almost along the view direction: raster's basis is as uncertain as the scene makes it.
    const ModelTransform transform{{LookAtStep{{0, 0, 0}, {0, 1, 0}, {0, 1, 1e-9f}}}, {}};
    const ModelMatrixError model = raster_model_error(transform);
    EXPECT_TRUE(std::isinf(model.bound[0][0]));
    EXPECT_TRUE(std::isinf(raster_world_position_error(model, {1, 0, 0}).x));
    // Exact steps: an entry every product keeps at zero is certain; the others carry the products' roundings.
    const ModelMatrixError exact_steps = raster_model_error({{TranslateStep{{1, 2, 3}}, ScaleStep{{2, 3, 4}}}, {}});
    EXPECT_EQ(exact_steps.bound[1][0], 0.0);
    EXPECT_GT(exact_steps.bound[3][0], 0.0);
    EXPECT_LT(exact_steps.bound[3][0], 1e-6);
}

}  // namespace
}  // namespace raster::oracle
