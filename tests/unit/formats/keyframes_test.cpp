// The raster format's keyframes: a node's translation, rotation and scale at increasing times, posed at any instant
// (between keys linearly, rotations by slerp; or held with step), after the node's fixed transform and before its
// parent's; a graph without keyframes has no animation; malformed keys are clear errors.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "raster/compat/scene_loader.h"
#include "raster/core/errors.h"
#include "raster/scene/animation.h"
#include "tests/support/placed_points.h"
#include "raster/transform/scene_pose.h"

namespace raster {
namespace {

using test_support::placed;
using test_support::expect_near;

const std::string kShape =
    "shapes:\n"
    "  tri: {vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0]], faces: [[0, 1, 2]]}\n";



Scene animated(const std::string& node_lines) {
    return parse_scene(kShape + "nodes:\n  - shape: tri\n" + node_lines, "scene.yaml");
}

std::string error_of(const std::string& node_lines) {
    try {
        animated(node_lines);
    } catch (const InputError& e) {
        return e.message();
    }
    return "";
}

TEST(Keyframes, aNodeMovesAndTurnsBetweenItsKeys) {
    Scene scene = animated(
        "    transform: [{translate: [0, 0, 1]}]\n"
        "    keyframes:\n"
        "      - {time: 0, translate: [0, 0, 0], rotate: {angle: 0, axis: [0, 1, 0]}}\n"
        "      - {time: 2, translate: [2, 0, 0], rotate: {angle: 90, axis: [0, 1, 0]}}\n");
    ASSERT_TRUE(scene.animation);
    EXPECT_EQ(scene.animation->start, 0.0f);
    EXPECT_EQ(scene.animation->end, 2.0f);
    // Loaded at time 0: only the fixed step moves (0, 0, 0).
    expect_near(placed(scene.meshes[0], {0, 0, 0}), {0, 0, 1});
    // At 1 s: the fixed step to (0, 0, 1), an eighth of a turn about +y to (sin 45, 0, cos 45), then halfway along x.
    pose_scene(scene, 1.0f);
    const float h = static_cast<float>(std::sqrt(0.5));
    expect_near(placed(scene.meshes[0], {0, 0, 0}), {h + 1.0f, 0, h});
}

TEST(Keyframes, aStepTrackHoldsEachKeyUntilTheNext) {
    Scene scene = animated(
        "    interpolation: step\n"
        "    keyframes: [{time: 0, scale: 1}, {time: 1, scale: 3}]\n");
    pose_scene(scene, 0.99f);
    expect_near(placed(scene.meshes[0], {1, 0, 0}), {1, 0, 0});
    pose_scene(scene, 1.0f);
    expect_near(placed(scene.meshes[0], {1, 0, 0}), {3, 0, 0});
}

TEST(Keyframes, aKeyedParentCarriesItsChildren) {
    Scene scene = parse_scene(kShape +
                                  "nodes:\n"
                                  "  - keyframes: [{time: 0, translate: [0, 0, 0]}, {time: 1, translate: [0, 4, 0]}]\n"
                                  "    children: [{shape: tri, transform: [{scale: 2}]}]\n",
                              "scene.yaml");
    pose_scene(scene, 0.5f);
    expect_near(placed(scene.meshes[0], {1, 0, 0}), {2, 2, 0});
}

TEST(Keyframes, aGraphWithoutKeyframesHasNoAnimation) {
    EXPECT_FALSE(parse_scene(kShape + "nodes: [{shape: tri}]\n", "scene.yaml").animation);
}

TEST(Keyframes, malformedKeysAreClearErrors) {
    EXPECT_NE(error_of("    keyframes: [{time: 1, scale: 1}, {time: 1, scale: 2}]\n").find("keyframe times must increase"),
              std::string::npos);
    EXPECT_NE(error_of("    keyframes: [{time: 0, rotate: [90, 0, 1, 0], quaternion: [1, 0, 0, 0]}]\n").find("not both"),
              std::string::npos);
    EXPECT_NE(error_of("    interpolation: step\n").find("the node has none"), std::string::npos);
    EXPECT_NE(error_of("    interpolation: cubic\n    keyframes: [{time: 0}]\n").find("linear or step"), std::string::npos);
    EXPECT_NE(error_of("    keyframes: [{time: 0, lookat: {eye: [0, 0, 1], target: [0, 0, 0]}}]\n").find("unknown key 'lookat'"),
              std::string::npos);
    EXPECT_NE(error_of("    keyframes: []\n").find("at least one key"), std::string::npos);
}

}  // namespace
}  // namespace raster
