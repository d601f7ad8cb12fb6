// glTF animations: the first animation's channels move their nodes (x, y, z, w rotations turned to raster's order,
// slerped; a cubic spline's three values a key), the scene is loaded posed at time 0, and malformed channels and
// samplers are refused with their JSON path.
#include "raster/gltf/gltf_animation.h"

#include <cmath>

#include <gtest/gtest.h>

#include "tests/support/placed_points.h"
#include "raster/transform/scene_pose.h"
#include "tests/support/gltf_builder.h"

namespace raster {
namespace {

using test_support::placed;
using test_support::expect_near;

using nlohmann::json;
using test_support::GltfBuilder;
using test_support::read_built;
using test_support::read_error;

const float kHalfRoot2 = static_cast<float>(std::sqrt(0.5));



// The triangle's node turned from rest to a quarter turn about +z between 1 s and 3 s, and moved along x.
GltfBuilder turning_triangle() {
    GltfBuilder b = GltfBuilder::one_triangle();
    const int times = b.accessor(std::vector<float>{1, 3}, "SCALAR", 5126);
    const int turns = b.accessor(std::vector<float>{0, 0, 0, 1, 0, 0, kHalfRoot2, kHalfRoot2}, "VEC4", 5126);
    const int moves = b.accessor(std::vector<float>{0, 0, 0, 4, 0, 0}, "VEC3", 5126);
    b.document["animations"] = {{{"channels", {{{"sampler", 0}, {"target", {{"node", 0}, {"path", "rotation"}}}},
                                               {{"sampler", 1}, {"target", {{"node", 0}, {"path", "translation"}}}}}},
                                 {"samplers", {{{"input", times}, {"output", turns}}, {{"input", times}, {"output", moves}}}}}};
    return b;
}

TEST(GltfAnimation, channelsMoveTheirNodeAndTheSceneLoadsPosedAtTimeZero) {
    Scene scene = read_built(turning_triangle());
    ASSERT_TRUE(scene.animation);
    EXPECT_EQ(scene.animation->start, 1.0f);
    EXPECT_EQ(scene.animation->end, 3.0f);
    // Before the first key: the first key's pose, the rest pose here.
    expect_near(placed(scene.meshes[0], {1, 0, 0}), {1, 0, 0});
    // Halfway: an eighth of a turn about +z, then two along x.
    pose_scene(scene, 2.0f);
    expect_near(placed(scene.meshes[0], {1, 0, 0}), {kHalfRoot2 + 2.0f, kHalfRoot2, 0});
}

TEST(GltfAnimation, aCubicSplineHasThreeValuesAKey) {
    GltfBuilder b = GltfBuilder::one_triangle();
    const int times = b.accessor(std::vector<float>{0, 2}, "SCALAR", 5126);
    // Key 0: in-tangent, value 0, out-tangent (1, 0, 0); key 1: in-tangent 0, value (0, 1, 0), out-tangent.
    const int values = b.accessor(std::vector<float>{9, 9, 9, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 1, 0, 9, 9, 9}, "VEC3", 5126);
    b.document["animations"] = {{{"channels", {{{"sampler", 0}, {"target", {{"node", 0}, {"path", "translation"}}}}}},
                                 {"samplers", {{{"input", times}, {"output", values}, {"interpolation", "CUBICSPLINE"}}}}}};
    Scene scene = read_built(b);
    pose_scene(scene, 0.5f);
    // u = 1/4: (u^3 - 2u^2 + u) * 2 * (1, 0, 0) + (-2u^3 + 3u^2) * (0, 1, 0).
    expect_near(placed(scene.meshes[0], {0, 0, 0}), {0.28125f, 0.15625f, 0});

    b.document["animations"][0]["samplers"][0]["interpolation"] = "LINEAR";  // 6 values for 2 keys
    EXPECT_NE(read_error(b).find("/animations/0/samplers/0/output: 6 values for 2 keys"), std::string::npos)
        << read_error(b);
}

TEST(GltfAnimation, malformedChannelsAndSamplersAreRefusedWithTheirPath) {
    GltfBuilder times = turning_triangle();
    times.document["accessors"][1]["count"] = 2;
    times.document["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 8}});
    // Times 0 and 0 (the triangle's first two floats): not increasing.
    times.document["accessors"][1]["bufferView"] = times.document["bufferViews"].size() - 1;
    EXPECT_NE(read_error(times).find("/animations/0/samplers/0/input: key 1's time"), std::string::npos) << read_error(times);

    GltfBuilder path = turning_triangle();
    path.document["animations"][0]["channels"][0]["target"]["path"] = "colour";
    EXPECT_NE(read_error(path).find("/animations/0/channels/0/target/path"), std::string::npos) << read_error(path);

    GltfBuilder matrix = turning_triangle();
    matrix.document["nodes"][0]["matrix"] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    EXPECT_NE(read_error(matrix).find("has a matrix"), std::string::npos) << read_error(matrix);

    GltfBuilder interpolation = turning_triangle();
    interpolation.document["animations"][0]["samplers"][0]["interpolation"] = "SMOOTH";
    EXPECT_NE(read_error(interpolation).find("/animations/0/samplers/0/interpolation"), std::string::npos);
}

TEST(GltfAnimation, weightsAloneMoveNothing) {
    GltfBuilder b = turning_triangle();
    b.document["animations"][0]["channels"] = {{{"sampler", 0}, {"target", {{"node", 0}, {"path", "weights"}}}}};
    EXPECT_FALSE(read_built(b).animation);
}

}  // namespace
}  // namespace raster
