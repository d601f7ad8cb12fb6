// Scene loader tests, the raster format: the documented defaults and value forms, transform chains, inline meshes.
#include <cstddef>
#include <cstdint>
#include <string>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <gtest/gtest.h>

#include "raster/core/errors.h"
#include "raster/compat/scene_loader.h"
#include "raster/transform/model_matrix.h"

namespace {

using raster::InputError;
using raster::parse_scene;
using raster::Scene;

void expect_vec3(const glm::vec3& v, float x, float y, float z) {
    EXPECT_NEAR(v.x, x, 1e-5f);
    EXPECT_NEAR(v.y, y, 1e-5f);
    EXPECT_NEAR(v.z, z, 1e-5f);
}

glm::vec3 apply(const raster::ModelTransform& transform, const glm::vec3& p) {
    const glm::mat4 m = raster::model_matrix(transform);
    const glm::vec4 q = m * glm::vec4(p, 1.0f);
    return glm::vec3(q.x, q.y, q.z) / q.w;
}

// A scene with one inline triangle and the given transform chain (YAML block list lines, indented 6 spaces).
Scene scene_with_transform(const std::string& steps) {
    return parse_scene("meshes:\n"
                       "  - vertices: [[1, 0, 0], [0, 1, 0], [0, 0, 1]]\n"
                       "    faces: [[0, 1, 2]]\n"
                       "    transform:\n" +
                           steps,
                       "scene.yaml");
}

const char* kTriangle = "  - vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0]]\n    faces: [[0, 1, 2]]\n";

// ---------------------------------------------------------------------------------------------------------------
// Defaults and value forms

TEST(SceneLoader, appliesDocumentedDefaults) {
    const Scene scene = parse_scene(std::string("lights:\n  - position: [5, 5, 5]\nmeshes:\n") + kTriangle, "scene.yaml");
    // image
    EXPECT_EQ(scene.settings.width, 640);
    EXPECT_EQ(scene.settings.height, 480);
    expect_vec3(scene.settings.background, 0, 0, 0);
    // camera
    expect_vec3(scene.camera.eye, 0, 0, 5);
    expect_vec3(scene.camera.target, 0, 0, 0);
    expect_vec3(scene.camera.up, 0, 1, 0);
    EXPECT_FLOAT_EQ(scene.camera.fov_y_degrees, 45.0f);
    EXPECT_FLOAT_EQ(scene.camera.near, 0.1f);
    EXPECT_FLOAT_EQ(scene.camera.far, 100.0f);
    // render
    EXPECT_EQ(scene.settings.samples, 1);
    EXPECT_EQ(scene.settings.pattern, raster::SamplePattern::standard);
    EXPECT_FALSE(scene.settings.msaa);
    EXPECT_EQ(scene.settings.shading, raster::ShadingMode::blinn_phong);
    EXPECT_FALSE(scene.settings.cull_backfaces);
    EXPECT_EQ(scene.settings.snap_bits, 8);
    expect_vec3(scene.settings.ambient_light, 1, 1, 1);
    // light
    ASSERT_EQ(scene.lights.size(), 1u);
    expect_vec3(scene.lights[0].position, 5, 5, 5);
    expect_vec3(scene.lights[0].color, 1, 1, 1);
    EXPECT_FLOAT_EQ(scene.lights[0].intensity, 1.0f);
    EXPECT_FALSE(scene.lights[0].attenuate);
    // mesh: identity transform, default material
    ASSERT_EQ(scene.meshes.size(), 1u);
    const raster::SceneMesh& mesh = scene.meshes[0];
    EXPECT_TRUE(mesh.transform.steps.empty());
    EXPECT_TRUE(mesh.transform.then_inverse_of.empty());
    expect_vec3(mesh.material.color, 1, 1, 1);
    expect_vec3(mesh.material.ambient, 0.1f, 0.1f, 0.1f);
    expect_vec3(mesh.material.diffuse, 0.7f, 0.7f, 0.7f);
    expect_vec3(mesh.material.specular, 0.2f, 0.2f, 0.2f);
    EXPECT_FLOAT_EQ(mesh.material.exponent, 32.0f);
}

TEST(SceneLoader, readsAnOrthographicCameraWithNearAtZero) {
    const Scene scene = parse_scene(std::string("camera: {projection: orthographic, height: 6, near: 0, far: 20}\n"
                                                "meshes:\n") + kTriangle,
                                    "scene.yaml");
    EXPECT_EQ(scene.camera.projection, raster::Projection::orthographic);
    EXPECT_FLOAT_EQ(scene.camera.ortho_height, 6.0f);
    EXPECT_FLOAT_EQ(scene.camera.near, 0.0f);
    EXPECT_FLOAT_EQ(scene.camera.far, 20.0f);
    // Perspective is the default.
    EXPECT_EQ(parse_scene(std::string("meshes:\n") + kTriangle, "scene.yaml").camera.projection,
              raster::Projection::perspective);
}

TEST(SceneLoader, readsDirectionalAndSpotLightsWithConesInDegrees) {
    const Scene scene = parse_scene(std::string("lights:\n"
                                                "  - {type: directional, direction: [0, -2, 0], intensity: 0.5}\n"
                                                "  - {type: spot, position: [0, 3, 0], direction: [0, -1, 0], "
                                                "inner_cone: 30, outer_cone: 45, attenuation: true, shadows: true}\n"
                                                "meshes:\n") + kTriangle,
                                    "scene.yaml");
    ASSERT_EQ(scene.lights.size(), 2u);
    EXPECT_EQ(scene.lights[0].type, raster::LightType::directional);
    expect_vec3(scene.lights[0].direction, 0, -2, 0);
    EXPECT_EQ(scene.lights[1].type, raster::LightType::spot);
    expect_vec3(scene.lights[1].position, 0, 3, 0);
    EXPECT_NEAR(scene.lights[1].inner_cone, 3.14159265 / 6, 1e-6);
    EXPECT_NEAR(scene.lights[1].outer_cone, 3.14159265 / 4, 1e-6);
    EXPECT_TRUE(scene.lights[1].shadows);
}

TEST(SceneLoader, noLightsByDefault) {
    const Scene scene = parse_scene(std::string("meshes:\n") + kTriangle, "scene.yaml");
    EXPECT_TRUE(scene.lights.empty());
}

TEST(SceneLoader, readsEveryDocumentedField) {
    const Scene scene = parse_scene(std::string("image: {width: 800, height: 600, background: [0.1, 0.2, 0.3]}\n"
                                                "camera: {eye: [0, 1, 5], target: [0, 0, -1], up: [0, 1, 0], fov: 60, "
                                                "near: 0.5, far: 50}\n"
                                                "render: {samples: 9, pattern: grid, msaa: true, shading: gouraud, "
                                                "cull: back, snap_bits: 4, ambient: [0.5, 0.25, 1]}\n"
                                                "lights:\n"
                                                "  - {position: [1, 2, 3], color: [1, 0.5, 0], intensity: 2, "
                                                "attenuation: true}\n"
                                                "meshes:\n") +
                                        kTriangle +
                                        "    material: {color: [0.8, 0.3, 0.2], ambient: [0.1, 0.2, 0.3], diffuse: 0.5,"
                                        " specular: 0.25, exponent: 8}\n",
                                    "scene.yaml");
    EXPECT_EQ(scene.settings.width, 800);
    EXPECT_EQ(scene.settings.height, 600);
    expect_vec3(scene.settings.background, 0.1f, 0.2f, 0.3f);
    expect_vec3(scene.camera.eye, 0, 1, 5);
    expect_vec3(scene.camera.target, 0, 0, -1);
    EXPECT_FLOAT_EQ(scene.camera.fov_y_degrees, 60.0f);
    EXPECT_FLOAT_EQ(scene.camera.near, 0.5f);
    EXPECT_FLOAT_EQ(scene.camera.far, 50.0f);
    EXPECT_EQ(scene.settings.samples, 9);
    EXPECT_EQ(scene.settings.pattern, raster::SamplePattern::grid);
    EXPECT_TRUE(scene.settings.msaa);
    EXPECT_EQ(scene.settings.shading, raster::ShadingMode::gouraud);
    EXPECT_TRUE(scene.settings.cull_backfaces);
    EXPECT_EQ(scene.settings.snap_bits, 4);
    expect_vec3(scene.settings.ambient_light, 0.5f, 0.25f, 1.0f);
    ASSERT_EQ(scene.lights.size(), 1u);
    expect_vec3(scene.lights[0].color, 1, 0.5f, 0);
    EXPECT_FLOAT_EQ(scene.lights[0].intensity, 2.0f);
    EXPECT_TRUE(scene.lights[0].attenuate);
    const raster::Material& m = scene.meshes.at(0).material;
    expect_vec3(m.color, 0.8f, 0.3f, 0.2f);
    expect_vec3(m.ambient, 0.1f, 0.2f, 0.3f);
    expect_vec3(m.diffuse, 0.5f, 0.5f, 0.5f);
    expect_vec3(m.specular, 0.25f, 0.25f, 0.25f);
    EXPECT_FLOAT_EQ(m.exponent, 8.0f);
}

// Every key of `render` that the test above leaves at its default, each set to a value of its own, lands in its own
// field: a key read into its neighbour's field (gooch's alpha into beta) or read and dropped shows here.
TEST(SceneLoader, readsEveryOtherRenderKeyIntoItsOwnField) {
    const Scene scene = parse_scene(
        std::string("render: {shading: gooch, cel_bands: 7, gooch: {blue: 0.1, yellow: 0.2, alpha: 0.3, beta: 0.7},\n"
                    "         edges: float, interpolation: affine, depth: fixed24, clipping: guard-band,\n"
                    "         hierarchical_z: false,\n"
                    "         shadows: {resolution: 256, bias: 0.01, slope_bias: 2.5, pcf: 3},\n"
                    "         transparency: {mode: weighted, max_fragments: 1000}}\n"
                    "meshes:\n") + kTriangle,
        "scene.yaml");
    const raster::RenderSettings& s = scene.settings;
    EXPECT_EQ(s.shading, raster::ShadingMode::gooch);
    EXPECT_EQ(s.cel_bands, 7);
    EXPECT_FLOAT_EQ(s.gooch.blue, 0.1f);
    EXPECT_FLOAT_EQ(s.gooch.yellow, 0.2f);
    EXPECT_FLOAT_EQ(s.gooch.alpha, 0.3f);
    EXPECT_FLOAT_EQ(s.gooch.beta, 0.7f);
    EXPECT_EQ(s.modes.edges, raster::EdgeArithmetic::float32);
    EXPECT_EQ(s.modes.interpolation, raster::Interpolation::affine);
    EXPECT_EQ(s.modes.depth, raster::DepthFormat::fixed24);
    EXPECT_EQ(s.modes.clipping, raster::Clipping::guard_band);
    EXPECT_FALSE(s.modes.hierarchical_z);
    EXPECT_EQ(s.shadows.resolution, 256);
    EXPECT_FLOAT_EQ(s.shadows.bias, 0.01f);
    EXPECT_FLOAT_EQ(s.shadows.slope_bias, 2.5f);
    EXPECT_EQ(s.shadows.pcf, 3);
    EXPECT_EQ(s.transparency.mode, raster::TransparencyMode::weighted);
    EXPECT_EQ(s.transparency.max_fragments, 1000);
}

TEST(SceneLoader, acceptsIntegersOrFloatsAndGreyColours) {
    const Scene scene = parse_scene(std::string("image: {width: 320.0, height: 200, background: 0.5}\n"
                                                "camera: {fov: 30, near: 1, far: 10.5}\n"
                                                "meshes:\n") +
                                        kTriangle,
                                    "scene.yaml");
    EXPECT_EQ(scene.settings.width, 320);
    EXPECT_EQ(scene.settings.height, 200);
    expect_vec3(scene.settings.background, 0.5f, 0.5f, 0.5f);
    EXPECT_FLOAT_EQ(scene.camera.near, 1.0f);
    EXPECT_FLOAT_EQ(scene.camera.far, 10.5f);
    // A fractional image size is not a size.
    EXPECT_THROW(parse_scene(std::string("image: {width: 320.5}\nmeshes:\n") + kTriangle, "scene.yaml"), InputError);
}


// ---------------------------------------------------------------------------------------------------------------
// Transform chains: applied to the object in the order listed

TEST(SceneLoader, translateThenScaleAppliesTranslateFirst) {
    // (1,0,0) + (1,0,0) = (2,0,0), then x2 = (4,0,0)
    const Scene scene = scene_with_transform("      - translate: [1, 0, 0]\n      - scale: 2\n");
    expect_vec3(apply(scene.meshes.at(0).transform, {1, 0, 0}), 4, 0, 0);
    expect_vec3(apply(scene.meshes.at(0).transform, {0, 1, 0}), 2, 2, 0);
}

TEST(SceneLoader, scaleThenTranslateAppliesScaleFirst) {
    // (1,0,0) x2 = (2,0,0), then + (1,0,0) = (3,0,0)
    const Scene scene = scene_with_transform("      - scale: 2\n      - translate: [1, 0, 0]\n");
    expect_vec3(apply(scene.meshes.at(0).transform, {1, 0, 0}), 3, 0, 0);
    expect_vec3(apply(scene.meshes.at(0).transform, {0, 1, 0}), 1, 2, 0);
}

TEST(SceneLoader, scaleTakesANumberOrAVector) {
    const Scene scene = scene_with_transform("      - scale: [1, 2, 3]\n");
    expect_vec3(apply(scene.meshes.at(0).transform, {1, 1, 1}), 1, 2, 3);
}

TEST(SceneLoader, rotateMapSyntaxIsDegreesAboutAxis) {
    // 90 degrees about +z (right-handed): x -> y, y -> -x.
    const Scene scene = scene_with_transform("      - rotate: {angle: 90, axis: [0, 0, 1]}\n");
    expect_vec3(apply(scene.meshes.at(0).transform, {1, 0, 0}), 0, 1, 0);
    expect_vec3(apply(scene.meshes.at(0).transform, {0, 1, 0}), -1, 0, 0);
    // 90 degrees about +y: x -> -z, z -> x.
    const Scene about_y = scene_with_transform("      - rotate: {angle: 90, axis: [0, 1, 0]}\n");
    expect_vec3(apply(about_y.meshes.at(0).transform, {1, 0, 0}), 0, 0, -1);
    expect_vec3(apply(about_y.meshes.at(0).transform, {0, 0, 1}), 1, 0, 0);
}

TEST(SceneLoader, rotateListSyntaxMatchesMapSyntax) {
    // [degrees, x, y, z]; the axis need not be unit length.
    const Scene scene = scene_with_transform("      - rotate: [90, 0, 0, 2]\n");
    expect_vec3(apply(scene.meshes.at(0).transform, {1, 0, 0}), 0, 1, 0);
    expect_vec3(apply(scene.meshes.at(0).transform, {0, 1, 0}), -1, 0, 0);
    // 120 degrees about (1,1,1) cycles the axes: x -> y -> z -> x.
    const Scene cyclic = scene_with_transform("      - rotate: [120, 1, 1, 1]\n");
    expect_vec3(apply(cyclic.meshes.at(0).transform, {1, 0, 0}), 0, 1, 0);
    expect_vec3(apply(cyclic.meshes.at(0).transform, {0, 1, 0}), 0, 0, 1);
}

TEST(SceneLoader, quaternionIsWxyzAndNormalised) {
    // [1, 0, 0, 1] normalises to (cos 45, 0, 0, sin 45): 90 degrees about +z.
    const Scene scene = scene_with_transform("      - quaternion: [1, 0, 0, 1]\n");
    expect_vec3(apply(scene.meshes.at(0).transform, {1, 0, 0}), 0, 1, 0);
    expect_vec3(apply(scene.meshes.at(0).transform, {0, 0, 1}), 0, 0, 1);
    // w first: [0, 1, 0, 0] is 180 degrees about +x.
    const Scene half_turn = scene_with_transform("      - quaternion: [0, 1, 0, 0]\n");
    expect_vec3(apply(half_turn.meshes.at(0).transform, {0, 1, 0}), 0, -1, 0);
    expect_vec3(apply(half_turn.meshes.at(0).transform, {1, 0, 0}), 1, 0, 0);
    // The identity quaternion.
    const Scene identity = scene_with_transform("      - quaternion: [2, 0, 0, 0]\n");
    expect_vec3(apply(identity.meshes.at(0).transform, {1, 2, 3}), 1, 2, 3);
}

TEST(SceneLoader, lookatPlacesObjectAtEyeFacingTarget) {
    const Scene scene =
        scene_with_transform("      - lookat: {eye: [1, 0, 0], target: [0, 0, 0], up: [0, 1, 0]}\n");
    const raster::ModelTransform& m = scene.meshes.at(0).transform;
    expect_vec3(apply(m, {0, 0, 0}), 1, 0, 0);   // the object's origin goes to eye
    expect_vec3(apply(m, {0, 0, -1}), 0, 0, 0);  // its -z axis points at the target
    expect_vec3(apply(m, {0, 1, 0}), 1, 1, 0);   // its +y follows up
    expect_vec3(apply(m, {1, 0, 0}), 1, 0, -1);  // +x = y cross z = (0,1,0) x (1,0,0) = (0,0,-1)
}

TEST(SceneLoader, chainOfThreeStepsComposesInOrder) {
    // (1,0,0): scale 2 -> (2,0,0); rotate 90 about z -> (0,2,0); translate (0,0,5) -> (0,2,5).
    const Scene scene = scene_with_transform(
        "      - scale: 2\n      - rotate: {angle: 90, axis: [0, 0, 1]}\n      - translate: [0, 0, 5]\n");
    expect_vec3(apply(scene.meshes.at(0).transform, {1, 0, 0}), 0, 2, 5);
}

// ---------------------------------------------------------------------------------------------------------------
// Inline meshes

TEST(SceneLoader, inlinePolygonsAreFanTriangulated) {
    const Scene scene = parse_scene("meshes:\n"
                                    "  - vertices: [[0, 0, 0], [2, 0, 0], [3, 1, 0], [1, 3, 0], [-1, 1, 0]]\n"
                                    "    faces: [[0, 1, 2, 3, 4], [1, 2, 3]]\n",
                                    "scene.yaml");
    const raster::MeshData& mesh = *scene.meshes.at(0).data;
    ASSERT_EQ(mesh.positions.size(), 5u);
    ASSERT_EQ(mesh.triangles.size(), 4u);  // 5-gon -> 3 triangles, plus one
    const uint32_t expected[4][3] = {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {1, 2, 3}};
    for (size_t t = 0; t < 4; ++t)
        for (int k = 0; k < 3; ++k) EXPECT_EQ(mesh.triangles[t].v[k], expected[t][k]) << "triangle " << t;
    expect_vec3(mesh.positions[3], 1, 3, 0);
    EXPECT_TRUE(mesh.face_colors.empty());
    EXPECT_TRUE(mesh.colors.empty());
    EXPECT_TRUE(mesh.normals.empty());
}

TEST(SceneLoader, inlineVertexColorsAndNormalsArePerVertex) {
    const Scene scene = parse_scene("meshes:\n"
                                    "  - vertices: [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]]\n"
                                    "    faces: [[0, 1, 2, 3]]\n"
                                    "    vertex_colors: [[1, 0, 0], [0, 1, 0], [0, 0, 1], 0.25]\n"
                                    "    normals: [[0, 0, 1], [0, 0, 1], [0, 1, 0], [1, 0, 0]]\n",
                                    "scene.yaml");
    const raster::MeshData& mesh = *scene.meshes.at(0).data;
    ASSERT_EQ(mesh.colors.size(), 4u);
    expect_vec3(mesh.colors[0], 1, 0, 0);
    expect_vec3(mesh.colors[1], 0, 1, 0);
    expect_vec3(mesh.colors[2], 0, 0, 1);
    expect_vec3(mesh.colors[3], 0.25f, 0.25f, 0.25f);  // a single number is grey
    ASSERT_EQ(mesh.normals.size(), 4u);
    expect_vec3(mesh.normals[2], 0, 1, 0);
    EXPECT_EQ(mesh.triangles.size(), 2u);
}

TEST(SceneLoader, inlineFaceColorsExpandToEveryTriangleOfTheirPolygon) {
    const Scene scene = parse_scene("meshes:\n"
                                    "  - vertices: [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [2, 2, 0], [3, 2, 0]]\n"
                                    "    faces: [[0, 1, 2, 3], [2, 4, 5], [0, 1, 2, 4, 5]]\n"
                                    "    face_colors: [[1, 0, 0], [0, 0, 1], 0.5]\n",
                                    "scene.yaml");
    const raster::MeshData& mesh = *scene.meshes.at(0).data;
    ASSERT_EQ(mesh.triangles.size(), 6u);  // 2 + 1 + 3
    ASSERT_EQ(mesh.face_colors.size(), 6u);
    expect_vec3(mesh.face_colors[0], 1, 0, 0);
    expect_vec3(mesh.face_colors[1], 1, 0, 0);
    expect_vec3(mesh.face_colors[2], 0, 0, 1);
    for (size_t t = 3; t < 6; ++t) expect_vec3(mesh.face_colors[t], 0.5f, 0.5f, 0.5f);
}

}  // namespace
