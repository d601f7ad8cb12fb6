// glTF scenes: node transforms kept as written (scale, rotation, translation; the child's chain before its
// parent's), one mesh placed by many nodes, node trees without cycles, the camera and point lights where their nodes
// put them, the metallic-roughness mapping and the alpha modes, and what the file leaves the caller to frame.
#include "raster/gltf/gltf_scene.h"

#include <cmath>
#include <variant>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "tests/support/placed_points.h"
#include "tests/support/gltf_builder.h"

namespace raster {
namespace {

using test_support::placed;
using test_support::expect_near;

using nlohmann::json;
using test_support::GltfBuilder;
using test_support::read_built;
using test_support::read_error;

const double kHalfRoot2 = std::sqrt(0.5);



TEST(GltfScene, aNodesTransformScalesThenRotatesThenTranslates) {
    GltfBuilder b = GltfBuilder::one_triangle();
    // A quarter turn about +z (x, y, z, w), after doubling and before moving one along x.
    b.document["nodes"][0]["scale"] = {2, 2, 2};
    b.document["nodes"][0]["rotation"] = {0, 0, kHalfRoot2, kHalfRoot2};
    b.document["nodes"][0]["translation"] = {1, 0, 0};
    const Scene scene = read_built(b);
    ASSERT_EQ(scene.meshes.size(), 1u);
    const std::vector<TransformStep>& steps = scene.meshes[0].transform.steps;
    ASSERT_EQ(steps.size(), 3u);
    ASSERT_TRUE(std::holds_alternative<ScaleStep>(steps[0]));
    ASSERT_TRUE(std::holds_alternative<QuaternionStep>(steps[1]));
    ASSERT_TRUE(std::holds_alternative<TranslateStep>(steps[2]));
    // The quaternion is stored w first.
    EXPECT_FLOAT_EQ(std::get<QuaternionStep>(steps[1]).wxyz.x, static_cast<float>(kHalfRoot2));
    EXPECT_FLOAT_EQ(std::get<QuaternionStep>(steps[1]).wxyz.w, static_cast<float>(kHalfRoot2));
    // (1, 0, 0): doubled to (2, 0, 0), turned to (0, 2, 0), moved to (1, 2, 0).
    expect_near(placed(scene.meshes[0], {1, 0, 0}), {1, 2, 0});
}

TEST(GltfScene, aMatrixNodeIsReadColumnByColumn) {
    GltfBuilder b = GltfBuilder::one_triangle();
    // Column-major: the last column is the translation (5, 6, 7).
    b.document["nodes"][0]["matrix"] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 5, 6, 7, 1};
    const Scene scene = read_built(b);
    expect_near(placed(scene.meshes[0], {1, 0, 0}), {6, 6, 7});
}

TEST(GltfScene, aChildsTransformComesBeforeItsParents) {
    GltfBuilder b;
    const int mesh = b.mesh({{"attributes", {{"POSITION", b.positions({0, 0, 0, 1, 0, 0, 0, 1, 0})}}}});
    const int child = b.node({{"mesh", mesh}, {"translation", {0, 1, 0}}}, false);
    b.node({{"scale", {3, 3, 3}}, {"children", {child}}});
    const Scene scene = read_built(b);
    ASSERT_EQ(scene.meshes.size(), 1u);
    // Moved up by one in the child, then the parent triples it: (0, 3, 0), not (0, 1, 0).
    expect_near(placed(scene.meshes[0], {0, 0, 0}), {0, 3, 0});
}

TEST(GltfScene, oneMeshPlacedByTwoNodesIsDrawnTwiceWhereEachPutsIt) {
    GltfBuilder b;
    const int mesh = b.mesh({{"attributes", {{"POSITION", b.positions({0, 0, 0, 1, 0, 0, 0, 1, 0})}}}});
    b.node({{"mesh", mesh}, {"translation", {-2, 0, 0}}});
    b.node({{"mesh", mesh}, {"translation", {2, 0, 0}}});
    const Scene scene = read_built(b);
    ASSERT_EQ(scene.meshes.size(), 2u);
    // One copy of the vertices, shared by both placements (instancing without copying).
    EXPECT_EQ(scene.meshes[0].data.get(), scene.meshes[1].data.get());
    expect_near(placed(scene.meshes[0], {0, 0, 0}), {-2, 0, 0});
    expect_near(placed(scene.meshes[1], {0, 0, 0}), {2, 0, 0});
    EXPECT_EQ(scene.meshes[0].source, "model.gltf#/meshes/0/primitives/0");
}

TEST(GltfScene, aNodeReachedTwiceIsRefused) {
    GltfBuilder cycle = GltfBuilder::one_triangle();
    cycle.document["nodes"][0]["children"] = {0};
    EXPECT_NE(read_error(cycle).find("/nodes/0: is reached twice"), std::string::npos) << read_error(cycle);

    GltfBuilder two_parents = GltfBuilder::one_triangle();
    two_parents.node({{"children", {0}}});
    EXPECT_NE(read_error(two_parents).find("is reached twice"), std::string::npos) << read_error(two_parents);

    GltfBuilder missing = GltfBuilder::one_triangle();
    missing.document["nodes"][0]["children"] = {7};
    EXPECT_NE(read_error(missing).find("/nodes/0/children/0: there is no node 7"), std::string::npos) << read_error(missing);
}

TEST(GltfScene, aTreeDeeperThanTheCapIsRefused) {
    GltfBuilder b = GltfBuilder::one_triangle();
    b.document["scenes"][0]["nodes"] = json::array();
    int below = 0;
    for (int depth = 0; depth < kMaxGltfNodeDepth; ++depth) below = b.node({{"children", {below}}}, false);
    b.document["scenes"][0]["nodes"].push_back(below);
    EXPECT_NE(read_error(b).find("nodes deep"), std::string::npos) << read_error(b);
    b.document["scenes"][0]["nodes"] = json::array({b.document["nodes"][below]["children"][0]});
    EXPECT_EQ(read_error(b), "");
}

TEST(GltfScene, theCameraLooksDownItsNodesMinusZFromItsOrigin) {
    GltfBuilder b = GltfBuilder::one_triangle();
    b.document["cameras"] = {{{"type", "perspective"},
                              {"perspective", {{"yfov", 0.5}, {"znear", 0.25}, {"zfar", 40}, {"aspectRatio", 2.0}}}}};
    // A quarter turn about +y turns -z to -x.
    b.node({{"camera", 0}, {"translation", {0, 0, 10}}, {"rotation", {0, kHalfRoot2, 0, kHalfRoot2}}});
    GltfSceneParts parts;
    const Scene scene = read_built(b, &parts);
    EXPECT_TRUE(parts.camera);
    expect_near(scene.camera.eye, {0, 0, 10});
    expect_near(glm::normalize(scene.camera.target - scene.camera.eye), {-1, 0, 0});
    expect_near(glm::normalize(scene.camera.up), {0, 1, 0});
    EXPECT_NEAR(scene.camera.fov_y_degrees, 0.5 * 180.0 / 3.14159265358979323846, 1e-4);
    EXPECT_FLOAT_EQ(scene.camera.near, 0.25f);
    EXPECT_FLOAT_EQ(scene.camera.far, 40.0f);
    EXPECT_EQ(scene.settings.width, 960);  // 480 high at the camera's aspect ratio of 2
}

TEST(GltfScene, anOrthographicCameraKeepsItsMagnificationsAndPlanes) {
    GltfBuilder b = GltfBuilder::one_triangle();
    b.document["cameras"] = {{{"type", "orthographic"},
                              {"orthographic", {{"xmag", 3.0}, {"ymag", 1.5}, {"znear", 0.0}, {"zfar", 12}}}}};
    b.node({{"camera", 0}, {"translation", {0, 0, 10}}});
    GltfSceneParts parts;
    const Scene scene = read_built(b, &parts);
    EXPECT_TRUE(parts.camera);
    EXPECT_EQ(scene.camera.projection, Projection::orthographic);
    expect_near(scene.camera.eye, {0, 0, 10});
    expect_near(glm::normalize(scene.camera.target - scene.camera.eye), {0, 0, -1});
    EXPECT_FLOAT_EQ(scene.camera.ortho_height, 3.0f);  // ymag is half the view's height
    EXPECT_FLOAT_EQ(scene.camera.near, 0.0f);
    EXPECT_FLOAT_EQ(scene.camera.far, 12.0f);
    EXPECT_EQ(scene.settings.width, 960);  // 480 high, at xmag / ymag = 2

    b.document["cameras"][0]["orthographic"]["ymag"] = 0;
    EXPECT_NE(read_error(b).find("/cameras/0/orthographic/ymag: must be > 0"), std::string::npos) << read_error(b);
    b.document["cameras"][0]["orthographic"]["ymag"] = 1;
    b.document["cameras"][0]["orthographic"]["zfar"] = 0;
    EXPECT_NE(read_error(b).find("/cameras/0/orthographic/zfar: must be > znear"), std::string::npos) << read_error(b);
}

TEST(GltfScene, primitivesWithoutATriangleAreNothingToDraw) {
    GltfBuilder b;
    b.node({{"mesh", b.mesh({{"attributes", {{"POSITION", b.positions({0, 0, 0, 1, 0, 0})}}}})}});
    b.document["cameras"] = {{{"type", "perspective"}, {"perspective", {{"yfov", 0.8}, {"znear", 0.1}}}}};
    b.node({{"camera", 0}});
    EXPECT_NE(read_error(b).find("places no triangles"), std::string::npos) << read_error(b);
}

TEST(GltfScene, aCameraWithoutZfarGetsAFarPlaneBeyondTheWholeScene) {
    GltfBuilder b = GltfBuilder::one_triangle();
    b.document["cameras"] = {{{"type", "perspective"}, {"perspective", {{"yfov", 0.8}, {"znear", 0.1}}}}};
    b.node({{"camera", 0}, {"translation", {0, 0, 50}}});
    const Scene scene = read_built(b);
    // The farthest vertex, (1, 0, 0) or (0, 1, 0), is sqrt(1 + 2500) from the eye.
    EXPECT_GT(scene.camera.far, std::sqrt(2501.0f));
    EXPECT_LT(scene.camera.far, 2.0f * std::sqrt(2501.0f));
}

TEST(GltfScene, lightsSitAtTheirNodesOriginAndShineDownItsMinusZ) {
    GltfBuilder b = GltfBuilder::one_triangle();
    b.document["extensions"]["KHR_lights_punctual"]["lights"] = {
        {{"type", "point"}, {"color", {1, 0.5, 0.25}}, {"intensity", 30}},
        {{"type", "directional"}, {"intensity", 2}},
        {{"type", "spot"}, {"spot", {{"innerConeAngle", 0.25}, {"outerConeAngle", 0.5}}}}};
    b.node({{"translation", {1, 2, 3}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
    // A quarter turn about +x turns -z to +y: the sun shines upwards.
    b.node({{"rotation", {kHalfRoot2, 0, 0, kHalfRoot2}}, {"extensions", {{"KHR_lights_punctual", {{"light", 1}}}}}});
    // A quarter turn about +y turns -z to -x.
    b.node({{"translation", {0, 4, 0}},
            {"rotation", {0, kHalfRoot2, 0, kHalfRoot2}},
            {"extensions", {{"KHR_lights_punctual", {{"light", 2}}}}}});
    GltfSceneParts parts;
    const Scene scene = read_built(b, &parts);
    EXPECT_TRUE(parts.lights);
    ASSERT_EQ(scene.lights.size(), 3u);
    EXPECT_EQ(scene.lights[0].type, LightType::point);
    expect_near(scene.lights[0].position, {1, 2, 3});
    expect_near(scene.lights[0].color, {1, 0.5f, 0.25f});
    EXPECT_FLOAT_EQ(scene.lights[0].intensity, 30.0f);
    EXPECT_TRUE(scene.lights[0].attenuate);  // candela: the inverse square law
    EXPECT_EQ(scene.lights[1].type, LightType::directional);
    expect_near(glm::normalize(scene.lights[1].direction), {0, 1, 0});
    EXPECT_FALSE(scene.lights[1].attenuate);  // lux: no distance
    EXPECT_EQ(scene.lights[2].type, LightType::spot);
    expect_near(scene.lights[2].position, {0, 4, 0});
    expect_near(glm::normalize(scene.lights[2].direction), {-1, 0, 0});
    EXPECT_FLOAT_EQ(scene.lights[2].inner_cone, 0.25f);
    EXPECT_FLOAT_EQ(scene.lights[2].outer_cone, 0.5f);
    EXPECT_TRUE(scene.lights[2].attenuate);

    b.document["extensions"]["KHR_lights_punctual"]["lights"][2]["spot"]["innerConeAngle"] = 0.75;
    EXPECT_NE(read_error(b).find("/extensions/KHR_lights_punctual/lights/2: a spot light's cone angles"),
              std::string::npos) << read_error(b);
}

TEST(GltfScene, withoutCameraOrLightTheCallerFramesAndLights) {
    GltfSceneParts parts{true, true};
    read_built(GltfBuilder::one_triangle(), &parts);
    EXPECT_FALSE(parts.camera);
    EXPECT_FALSE(parts.lights);
}

TEST(GltfScene, aRequiredExtensionRasterDoesNotReadIsRefused) {
    GltfBuilder b = GltfBuilder::one_triangle();
    b.document["extensionsRequired"] = {"KHR_draco_mesh_compression"};
    EXPECT_NE(read_error(b).find("/extensionsRequired: the file needs KHR_draco_mesh_compression"), std::string::npos)
        << read_error(b);
}

TEST(GltfScene, withoutScenesEveryRootNodeIsDrawn) {
    GltfBuilder b;
    const int mesh = b.mesh({{"attributes", {{"POSITION", b.positions({0, 0, 0, 1, 0, 0, 0, 1, 0})}}}});
    const int child = b.node({{"mesh", mesh}}, false);
    b.node({{"children", {child}}}, false);
    b.node({{"mesh", mesh}}, false);
    b.document.erase("scenes");
    EXPECT_EQ(read_built(b).meshes.size(), 2u);
}

TEST(GltfScene, metallicRoughnessMapsToDiffuseSpecularAndExponent) {
    GltfBuilder b = GltfBuilder::one_triangle();
    b.document["materials"] = {{{"pbrMetallicRoughness",
                                 {{"baseColorFactor", {0.5, 0.25, 1.0, 1.0}}, {"metallicFactor", 0.0}, {"roughnessFactor", 0.5}}}}};
    b.document["meshes"][0]["primitives"][0]["material"] = 0;
    const Material& m = read_built(b).meshes[0].material;
    expect_near(m.color, {0.5f, 0.25f, 1.0f});
    expect_near(m.diffuse, {1, 1, 1});
    expect_near(m.specular, {0.04f, 0.04f, 0.04f});
    EXPECT_FLOAT_EQ(m.exponent, 30.0f);  // a = 0.5^2: 2 / a^2 - 2
    EXPECT_FLOAT_EQ(m.opacity, 1.0f);

    // A metal: no diffuse, its base colour as specular.
    b.document["materials"][0]["pbrMetallicRoughness"]["metallicFactor"] = 1.0;
    const Material& metal = read_built(b).meshes[0].material;
    expect_near(metal.diffuse, {0, 0, 0});
    expect_near(metal.specular, {0.5f, 0.25f, 1.0f});
}

TEST(GltfScene, aPrimitiveWithoutMaterialGetsRastersDefault) {
    const Material& m = read_built(GltfBuilder::one_triangle()).meshes[0].material;
    const Material defaults;
    EXPECT_EQ(m.diffuse, defaults.diffuse);
    EXPECT_EQ(m.specular, defaults.specular);
    EXPECT_EQ(m.exponent, defaults.exponent);
}

TEST(GltfScene, alphaModesBlendByTheFactorAndMaskCutsBelowTheCutoff) {
    GltfBuilder b = GltfBuilder::one_triangle();
    b.document["meshes"][0]["primitives"][0]["material"] = 0;
    b.document["materials"] = {{{"alphaMode", "BLEND"}, {"pbrMetallicRoughness", {{"baseColorFactor", {1, 1, 1, 0.25}}}}}};
    EXPECT_FLOAT_EQ(read_built(b).meshes[0].material.opacity, 0.25f);

    b.document["materials"][0]["alphaMode"] = "MASK";  // the default cut-off, 0.5
    EXPECT_NE(read_error(b).find("places no triangles"), std::string::npos) << read_error(b);
    b.document["materials"][0]["alphaCutoff"] = 0.2;
    const Scene kept = read_built(b);
    ASSERT_EQ(kept.meshes.size(), 1u);
    EXPECT_FLOAT_EQ(kept.meshes[0].material.opacity, 1.0f);

    // A primitive cut away is never read: its broken accessor does not matter.
    b.document["materials"][0]["alphaCutoff"] = 0.5;
    b.node({{"mesh", b.mesh({{"attributes", {{"POSITION", 99}}}})}});
    b.document["meshes"][0]["primitives"][0]["material"] = json();
    b.document["meshes"][1]["primitives"][0]["material"] = 0;
    EXPECT_EQ(read_built(b).meshes.size(), 1u);
    b.document["meshes"][0]["primitives"][0]["material"] = 0;

    b.document["materials"][0]["alphaMode"] = "HALF";
    EXPECT_NE(read_error(b).find("/materials/0/alphaMode"), std::string::npos) << read_error(b);
}

TEST(GltfScene, vertexColoursCarryTheBaseColourFactor) {
    GltfBuilder b = GltfBuilder::one_triangle();
    const int colours = b.accessor(std::vector<uint8_t>{255, 0, 128, 255, 0, 255, 0, 255, 0, 0, 255, 255}, "VEC4", 5121, true);
    b.document["meshes"][0]["primitives"][0]["attributes"]["COLOR_0"] = colours;
    b.document["meshes"][0]["primitives"][0]["material"] = 0;
    b.document["materials"] = {{{"pbrMetallicRoughness", {{"baseColorFactor", {0.5, 1, 1, 1}}}}}};
    const Scene scene = read_built(b);
    // No normals: each triangle has its own corners, in order, so vertex 0 is the first corner.
    ASSERT_EQ(scene.meshes[0].data->colors.size(), 3u);
    expect_near(scene.meshes[0].data->colors[0], {0.5f, 0.0f, 128.0f / 255.0f});
    expect_near(scene.meshes[0].data->colors[1], {0.0f, 1.0f, 0.0f});
}

}  // namespace
}  // namespace raster
