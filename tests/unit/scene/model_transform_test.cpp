// A model transform's checks: each kind of bad step named, and a chain whose product could leave float's range
// refused, through the scene's validation and through a scene file.
#include "raster/scene/model_transform.h"

#include <cmath>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "raster/core/errors.h"
#include "raster/compat/scene_loader.h"
#include "raster/scene/validation.h"

namespace raster {
namespace {

std::string problem_of(const std::vector<TransformStep>& steps) {
    return model_transform_problem({steps, {}}).value_or("");
}

TEST(ModelTransform, eachKindOfStepThatCannotBeComposedIsNamed) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    EXPECT_EQ(problem_of({TranslateStep{{0, nan, 0}}}), "a translate step is not finite");
    EXPECT_EQ(problem_of({ScaleStep{{1, 1, INFINITY}}}), "a scale step is not finite");
    EXPECT_EQ(problem_of({RotateStep{30, {0, 0, 0}}}), "a rotate step's axis is zero");
    EXPECT_EQ(problem_of({RotateStep{nan, {0, 0, 1}}}), "a rotate step is not finite");
    EXPECT_EQ(problem_of({QuaternionStep{{0, 0, 0, 0}}}), "a quaternion step is zero");
    EXPECT_NE(problem_of({LookAtStep{{1, 1, 1}, {1, 1, 1}, {0, 1, 0}}}).find("a lookat step: "), std::string::npos);
    MatrixStep matrix;
    matrix.matrix[2][1] = nan;
    EXPECT_EQ(problem_of({matrix}), "a matrix step is not finite");
    // The seed 001 camera chain is checked too.
    EXPECT_EQ(model_transform_problem({{}, {ScaleStep{{nan, 1, 1}}}}).value_or(""), "a scale step is not finite");
}

TEST(ModelTransform, theMagnitudeBoundMultipliesEachStepsRowSum) {
    EXPECT_EQ(model_magnitude_bound({}), 1.0);
    EXPECT_EQ(model_magnitude_bound({TranslateStep{{0, -7, 2}}}), 8.0);
    EXPECT_EQ(model_magnitude_bound({ScaleStep{{0.5f, -3, 2}}, TranslateStep{{1, 0, 0}}}), 6.0);
    EXPECT_NEAR(model_magnitude_bound({RotateStep{45, {1, 1, 0}}}), std::sqrt(3.0), 1e-9);
    // A real product never exceeds it: a scale of 3 then a translation of 7 reaches 3 + 7 = 10 <= 3 * 8.
    EXPECT_GE(model_magnitude_bound({ScaleStep{{3, 3, 3}}, TranslateStep{{7, 7, 7}}}), 10.0);
}

TEST(ModelTransform, aChainThatCouldLeaveFloatsRangeIsRefusedJustPastTheLimit) {
    EXPECT_FALSE(model_transform_problem({{ScaleStep{{1e15f, 1, 1}}, ScaleStep{{1e15f, 1, 1}}}, {}}));
    const auto problem = model_transform_problem({{ScaleStep{{1e15f, 1, 1}}, ScaleStep{{2e15f, 1, 1}}}, {}});
    ASSERT_TRUE(problem);
    EXPECT_NE(problem->find("beyond the 1e+30"), std::string::npos) << *problem;
}

TEST(ModelTransform, aSceneFileWithSuchAChainIsRefusedNamingTheMesh) {
    const std::string text =
        "meshes:\n  - vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0]]\n    faces: [[0, 1, 2]]\n    transform:\n"
        "      - scale: 1e20\n      - scale: 1e20\n";
    try {
        parse_scene(text, "huge.yaml");
        FAIL() << "a transform of 1e40 was accepted";
    } catch (const InputError& error) {
        const std::string message = error.what();
        EXPECT_NE(message.find("huge.yaml"), std::string::npos) << message;
        EXPECT_NE(message.find("may reach 1e+40"), std::string::npos) << message;
    }
}

}  // namespace
}  // namespace raster
