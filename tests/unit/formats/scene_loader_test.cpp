// Scene loader tests: README defaults, transform chains, inline meshes, seed 003 JSON, format detection, and one test per class of bad input.
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <gtest/gtest.h>

#include "tests/support/temp_dir.h"

#include "raster/core/errors.h"
#include "raster/formats/scene_loader.h"

namespace {

namespace fs = std::filesystem;
using raster::InputError;
using raster::parse_scene;
using raster::Scene;

using raster::test_support::TempDir;

testing::AssertionResult contains(const std::string& text, const std::string& part) {
    if (text.find(part) != std::string::npos) return testing::AssertionSuccess();
    return testing::AssertionFailure() << "'" << text << "' does not contain '" << part << "'";
}

// What parse_scene threw for input that must be rejected.
struct Failure {
    bool thrown = false;
    std::string file;
    int line = -1;
    int column = -1;
    std::string message;
    std::string what;
};

Failure scene_failure(const std::string& text, const std::string& path = "scene.yaml") {
    Failure f;
    try {
        parse_scene(text, path);
    } catch (const InputError& e) {
        f.thrown = true;
        f.file = e.file();
        f.line = e.line();
        f.column = e.column();
        f.message = e.message();
        f.what = e.what();
    }
    return f;
}

// Checks a rejection: thrown as InputError, naming `file` at line:column (column 0 = not checked), and the text
// of the full message starting with "file:line:" as the README's example shows.
void expect_failure_at(const Failure& f, const std::string& file, int line, int column, const std::string& problem) {
    ASSERT_TRUE(f.thrown) << "no InputError for input that must be rejected (" << problem << ")";
    EXPECT_EQ(f.file, file) << f.what;
    EXPECT_EQ(f.line, line) << f.what;
    if (column > 0) {
        EXPECT_EQ(f.column, column) << f.what;
    }
    EXPECT_TRUE(contains(f.what, file + ":" + std::to_string(line) + ":"));
    EXPECT_TRUE(contains(f.message, problem));
}

void expect_vec3(const glm::vec3& v, float x, float y, float z) {
    EXPECT_NEAR(v.x, x, 1e-5f);
    EXPECT_NEAR(v.y, y, 1e-5f);
    EXPECT_NEAR(v.z, z, 1e-5f);
}

glm::vec3 apply(const glm::mat4& m, const glm::vec3& p) {
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
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) EXPECT_FLOAT_EQ(mesh.model[c][r], c == r ? 1.0f : 0.0f);
    expect_vec3(mesh.material.color, 1, 1, 1);
    expect_vec3(mesh.material.ambient, 0.1f, 0.1f, 0.1f);
    expect_vec3(mesh.material.diffuse, 0.7f, 0.7f, 0.7f);
    expect_vec3(mesh.material.specular, 0.2f, 0.2f, 0.2f);
    EXPECT_FLOAT_EQ(mesh.material.exponent, 32.0f);
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
    EXPECT_TRUE(scene_failure(std::string("image: {width: 320.5}\nmeshes:\n") + kTriangle).thrown);
}

TEST(SceneLoader, meshesAreRequired) {
    const Failure f = scene_failure("image: {width: 10, height: 10}\n");
    expect_failure_at(f, "scene.yaml", 1, 0, "meshes");
}

// ---------------------------------------------------------------------------------------------------------------
// Transform chains: applied to the object in the order listed

TEST(SceneLoader, translateThenScaleAppliesTranslateFirst) {
    // (1,0,0) + (1,0,0) = (2,0,0), then x2 = (4,0,0)
    const Scene scene = scene_with_transform("      - translate: [1, 0, 0]\n      - scale: 2\n");
    expect_vec3(apply(scene.meshes.at(0).model, {1, 0, 0}), 4, 0, 0);
    expect_vec3(apply(scene.meshes.at(0).model, {0, 1, 0}), 2, 2, 0);
}

TEST(SceneLoader, scaleThenTranslateAppliesScaleFirst) {
    // (1,0,0) x2 = (2,0,0), then + (1,0,0) = (3,0,0)
    const Scene scene = scene_with_transform("      - scale: 2\n      - translate: [1, 0, 0]\n");
    expect_vec3(apply(scene.meshes.at(0).model, {1, 0, 0}), 3, 0, 0);
    expect_vec3(apply(scene.meshes.at(0).model, {0, 1, 0}), 1, 2, 0);
}

TEST(SceneLoader, scaleTakesANumberOrAVector) {
    const Scene scene = scene_with_transform("      - scale: [1, 2, 3]\n");
    expect_vec3(apply(scene.meshes.at(0).model, {1, 1, 1}), 1, 2, 3);
}

TEST(SceneLoader, rotateMapSyntaxIsDegreesAboutAxis) {
    // 90 degrees about +z (right-handed): x -> y, y -> -x.
    const Scene scene = scene_with_transform("      - rotate: {angle: 90, axis: [0, 0, 1]}\n");
    expect_vec3(apply(scene.meshes.at(0).model, {1, 0, 0}), 0, 1, 0);
    expect_vec3(apply(scene.meshes.at(0).model, {0, 1, 0}), -1, 0, 0);
    // 90 degrees about +y: x -> -z, z -> x.
    const Scene about_y = scene_with_transform("      - rotate: {angle: 90, axis: [0, 1, 0]}\n");
    expect_vec3(apply(about_y.meshes.at(0).model, {1, 0, 0}), 0, 0, -1);
    expect_vec3(apply(about_y.meshes.at(0).model, {0, 0, 1}), 1, 0, 0);
}

TEST(SceneLoader, rotateListSyntaxMatchesMapSyntax) {
    // [degrees, x, y, z]; the axis need not be unit length.
    const Scene scene = scene_with_transform("      - rotate: [90, 0, 0, 2]\n");
    expect_vec3(apply(scene.meshes.at(0).model, {1, 0, 0}), 0, 1, 0);
    expect_vec3(apply(scene.meshes.at(0).model, {0, 1, 0}), -1, 0, 0);
    // 120 degrees about (1,1,1) cycles the axes: x -> y -> z -> x.
    const Scene cyclic = scene_with_transform("      - rotate: [120, 1, 1, 1]\n");
    expect_vec3(apply(cyclic.meshes.at(0).model, {1, 0, 0}), 0, 1, 0);
    expect_vec3(apply(cyclic.meshes.at(0).model, {0, 1, 0}), 0, 0, 1);
}

TEST(SceneLoader, quaternionIsWxyzAndNormalised) {
    // [1, 0, 0, 1] normalises to (cos 45, 0, 0, sin 45): 90 degrees about +z.
    const Scene scene = scene_with_transform("      - quaternion: [1, 0, 0, 1]\n");
    expect_vec3(apply(scene.meshes.at(0).model, {1, 0, 0}), 0, 1, 0);
    expect_vec3(apply(scene.meshes.at(0).model, {0, 0, 1}), 0, 0, 1);
    // w first: [0, 1, 0, 0] is 180 degrees about +x.
    const Scene half_turn = scene_with_transform("      - quaternion: [0, 1, 0, 0]\n");
    expect_vec3(apply(half_turn.meshes.at(0).model, {0, 1, 0}), 0, -1, 0);
    expect_vec3(apply(half_turn.meshes.at(0).model, {1, 0, 0}), 1, 0, 0);
    // The identity quaternion.
    const Scene identity = scene_with_transform("      - quaternion: [2, 0, 0, 0]\n");
    expect_vec3(apply(identity.meshes.at(0).model, {1, 2, 3}), 1, 2, 3);
}

TEST(SceneLoader, lookatPlacesObjectAtEyeFacingTarget) {
    const Scene scene =
        scene_with_transform("      - lookat: {eye: [1, 0, 0], target: [0, 0, 0], up: [0, 1, 0]}\n");
    const glm::mat4& m = scene.meshes.at(0).model;
    expect_vec3(apply(m, {0, 0, 0}), 1, 0, 0);   // the object's origin goes to eye
    expect_vec3(apply(m, {0, 0, -1}), 0, 0, 0);  // its -z axis points at the target
    expect_vec3(apply(m, {0, 1, 0}), 1, 1, 0);   // its +y follows up
    expect_vec3(apply(m, {1, 0, 0}), 1, 0, -1);  // +x = y cross z = (0,1,0) x (1,0,0) = (0,0,-1)
}

TEST(SceneLoader, chainOfThreeStepsComposesInOrder) {
    // (1,0,0): scale 2 -> (2,0,0); rotate 90 about z -> (0,2,0); translate (0,0,5) -> (0,2,5).
    const Scene scene = scene_with_transform(
        "      - scale: 2\n      - rotate: {angle: 90, axis: [0, 0, 1]}\n      - translate: [0, 0, 5]\n");
    expect_vec3(apply(scene.meshes.at(0).model, {1, 0, 0}), 0, 2, 5);
}

TEST(SceneLoader, transformErrorsPointAtTheStep) {
    expect_failure_at(scene_failure(std::string("meshes:\n") + kTriangle + "    transform:\n      - rotate: [90, 0, 0, 0]\n"),
                      "scene.yaml", 5, 17, "axis");
    expect_failure_at(scene_failure(std::string("meshes:\n") + kTriangle + "    transform:\n      - shear: 2\n"),
                      "scene.yaml", 5, 9, "unknown key 'shear'");
}

// ---------------------------------------------------------------------------------------------------------------
// Inline meshes

TEST(SceneLoader, inlinePolygonsAreFanTriangulated) {
    const Scene scene = parse_scene("meshes:\n"
                                    "  - vertices: [[0, 0, 0], [2, 0, 0], [3, 1, 0], [1, 3, 0], [-1, 1, 0]]\n"
                                    "    faces: [[0, 1, 2, 3, 4], [1, 2, 3]]\n",
                                    "scene.yaml");
    const raster::MeshData& mesh = scene.meshes.at(0).data;
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
    const raster::MeshData& mesh = scene.meshes.at(0).data;
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
    const raster::MeshData& mesh = scene.meshes.at(0).data;
    ASSERT_EQ(mesh.triangles.size(), 6u);  // 2 + 1 + 3
    ASSERT_EQ(mesh.face_colors.size(), 6u);
    expect_vec3(mesh.face_colors[0], 1, 0, 0);
    expect_vec3(mesh.face_colors[1], 1, 0, 0);
    expect_vec3(mesh.face_colors[2], 0, 0, 1);
    for (size_t t = 3; t < 6; ++t) expect_vec3(mesh.face_colors[t], 0.5f, 0.5f, 0.5f);
}

TEST(SceneLoader, inlineAttributeCountMismatchIsAnError) {
    const std::string mesh = "meshes:\n"
                             "  - vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0]]\n"
                             "    faces: [[0, 1, 2]]\n";
    expect_failure_at(scene_failure(mesh + "    vertex_colors: [[1, 0, 0], [0, 1, 0]]\n"), "scene.yaml", 4, 20,
                      "one entry per vertex");
    expect_failure_at(scene_failure(mesh + "    face_colors: [[1, 0, 0], [0, 1, 0]]\n"), "scene.yaml", 4, 18,
                      "one entry per face");
    expect_failure_at(scene_failure(mesh + "    normals: [[0, 0, 1]]\n"), "scene.yaml", 4, 14, "one entry per vertex");
    // A face needs 3 corners.
    expect_failure_at(scene_failure("meshes:\n  - vertices: [[0, 0, 0], [1, 0, 0]]\n    faces: [[0, 1]]\n"), "scene.yaml",
                      3, 13, "3 or more");
    // Either a file or inline vertices.
    EXPECT_TRUE(scene_failure("meshes:\n  - faces: [[0, 1, 2]]\n").thrown);
}

// ---------------------------------------------------------------------------------------------------------------
// Seed 003 JSON scenes

// An OBJ triangle with normals that point away from the face normal (+z), so dropping them is observable.
const char* kObjWithNormals = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 1 0 0\nf 1//1 2//1 3//1\n";

std::string seed003_scene(const std::string& obj, const std::string& near, const std::string& far) {
    return "{\n"
           "  \"eye\": [0, 1, 4],\n"
           "  \"lookat\": [0, 0, 0],\n"
           "  \"up\": [0, 1, 0],\n"
           "  \"fov_angle\": 60,\n"
           "  \"width\": 64,\n"
           "  \"height\": 48,\n"
           "  \"near\": " + near + ",\n"
           "  \"far\": " + far + ",\n"
           "  \"lights\": [{\"position\": [2, 3, 4], \"color\": [1, 0.5, 0.25]}],\n"
           "  \"meshes\": [{\"obj\": \"" + obj + "\", \"ambient\": [0.1, 0.2, 0.3], \"diffuse\": [0.4, 0.5, 0.6],\n"
           "              \"specular\": [0.7, 0.8, 0.9], \"phong_exponent\": 12}]\n"
           "}\n";
}

TEST(SceneLoader, seed003SceneInTheDocumentsKeySetLoads) {
    TempDir dir;
    dir.write("models/tri.obj", kObjWithNormals);
    const fs::path path = dir.write("scene.json", seed003_scene("models/tri.obj", "-0.5", "-50"));
    const Scene scene = raster::load_scene(path);
    EXPECT_EQ(scene.settings.width, 64);
    EXPECT_EQ(scene.settings.height, 48);
    expect_vec3(scene.camera.eye, 0, 1, 4);
    expect_vec3(scene.camera.target, 0, 0, 0);
    expect_vec3(scene.camera.up, 0, 1, 0);
    EXPECT_FLOAT_EQ(scene.camera.fov_y_degrees, 60.0f);
    // README: the document's default shading is per-fragment Blinn-Phong.
    EXPECT_EQ(scene.settings.shading, raster::ShadingMode::blinn_phong);
    ASSERT_EQ(scene.lights.size(), 1u);
    expect_vec3(scene.lights[0].position, 2, 3, 4);
    expect_vec3(scene.lights[0].color, 1, 0.5f, 0.25f);
    ASSERT_EQ(scene.meshes.size(), 1u);
    const raster::SceneMesh& mesh = scene.meshes[0];
    EXPECT_EQ(mesh.data.triangles.size(), 1u);
    expect_vec3(mesh.material.ambient, 0.1f, 0.2f, 0.3f);
    expect_vec3(mesh.material.diffuse, 0.4f, 0.5f, 0.6f);
    expect_vec3(mesh.material.specular, 0.7f, 0.8f, 0.9f);
    EXPECT_FLOAT_EQ(mesh.material.exponent, 12.0f);
}

TEST(SceneLoader, seed003ObjPathIsRelativeToTheSceneFile) {
    TempDir dir;
    dir.write("deep/models/tri.obj", kObjWithNormals);
    const fs::path path = dir.write("deep/scene.json", seed003_scene("models/tri.obj", "-0.1", "-100"));
    EXPECT_EQ(raster::load_scene(path).meshes.at(0).data.triangles.size(), 1u);
    // The same text given with a path in another folder does not find the mesh.
    const Failure f = scene_failure(seed003_scene("models/tri.obj", "-0.1", "-100"), (dir.path() / "x.json").string());
    expect_failure_at(f, (dir.path() / "x.json").string(), 11, 22, "models/tri.obj");
    // An absolute path works from anywhere.
    const std::string absolute = (dir.path() / "deep/models/tri.obj").string();
    EXPECT_EQ(parse_scene(seed003_scene(absolute, "-0.1", "-100"), "elsewhere/x.json").meshes.size(), 1u);
}

TEST(SceneLoader, seed003NegativeNearFarBecomeDistances) {
    TempDir dir;
    dir.write("tri.obj", kObjWithNormals);
    const Scene book = parse_scene(seed003_scene("tri.obj", "-0.5", "-50"), (dir.path() / "s.json").string());
    EXPECT_FLOAT_EQ(book.camera.near, 0.5f);
    EXPECT_FLOAT_EQ(book.camera.far, 50.0f);
    // Positive distances are accepted unchanged.
    const Scene distances = parse_scene(seed003_scene("tri.obj", "2", "20"), (dir.path() / "s.json").string());
    EXPECT_FLOAT_EQ(distances.camera.near, 2.0f);
    EXPECT_FLOAT_EQ(distances.camera.far, 20.0f);
}

TEST(SceneLoader, seed003MixedSignsNearFarIsAnError) {
    TempDir dir;
    dir.write("tri.obj", kObjWithNormals);
    const std::string name = (dir.path() / "s.json").string();
    // "  \"near\": " is 10 characters: the value starts in column 11 of line 8.
    expect_failure_at(scene_failure(seed003_scene("tri.obj", "-0.1", "100"), name), name, 8, 11, "near");
    expect_failure_at(scene_failure(seed003_scene("tri.obj", "0.1", "-100"), name), name, 8, 11, "near");
    // Book order reversed (near -100 is farther than far -0.1): far is not beyond near.
    expect_failure_at(scene_failure(seed003_scene("tri.obj", "-100", "-0.1"), name), name, 9, 10, "far");
}

TEST(SceneLoader, seed003DropsNormalsFromTheObj) {
    TempDir dir;
    dir.write("tri.obj", kObjWithNormals);
    const Scene scene = parse_scene(seed003_scene("tri.obj", "-0.1", "-100"), (dir.path() / "s.json").string());
    EXPECT_TRUE(scene.meshes.at(0).data.normals.empty());
    // The same OBJ in a raster scene keeps them.
    const Scene raster_scene = parse_scene("meshes:\n  - file: tri.obj\n", (dir.path() / "s.yaml").string());
    ASSERT_EQ(raster_scene.meshes.at(0).data.normals.size(), 3u);
    expect_vec3(raster_scene.meshes[0].data.normals[0], 1, 0, 0);
}

TEST(SceneLoader, seed003UnknownKeysAreWarningsNotErrors) {
    TempDir dir;
    dir.write("tri.obj", kObjWithNormals);
    std::string text = seed003_scene("tri.obj", "-0.1", "-100");
    text.insert(text.find('{') + 1, "\n  \"antialias\": 4,");
    testing::internal::CaptureStderr();
    const Scene scene = parse_scene(text, (dir.path() / "s.json").string());
    const std::string warnings = testing::internal::GetCapturedStderr();
    EXPECT_EQ(scene.meshes.size(), 1u);
    EXPECT_TRUE(contains(warnings, "antialias"));
    EXPECT_TRUE(contains(warnings, "warning"));
}

// ---------------------------------------------------------------------------------------------------------------
// Format detection by content

TEST(SceneLoader, detectsFormatByContentNotExtension) {
    TempDir dir;
    dir.write("tri.obj", kObjWithNormals);
    // A raster scene written as JSON, in a .json file: read as a raster scene (image.width, inline mesh).
    const Scene raster_json = parse_scene(
        "{\"image\": {\"width\": 20, \"height\": 10}, \"camera\": {\"fov\": 30},\n"
        " \"meshes\": [{\"vertices\": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], \"faces\": [[0, 1, 2]]}]}\n",
        (dir.path() / "raster.json").string());
    EXPECT_EQ(raster_json.settings.width, 20);
    EXPECT_EQ(raster_json.settings.height, 10);
    EXPECT_FLOAT_EQ(raster_json.camera.fov_y_degrees, 30.0f);
    // A seed 003 scene in the same extension: read as seed 003 (width at the top level, obj meshes).
    const Scene seed = parse_scene(seed003_scene("tri.obj", "-0.1", "-100"), (dir.path() / "seed.json").string());
    EXPECT_EQ(seed.settings.width, 64);
    EXPECT_TRUE(seed.meshes.at(0).data.normals.empty());
    // And a seed 003 scene written as YAML in a .yaml file is still seed 003.
    const Scene seed_yaml = parse_scene("eye: [0, 0, 3]\nlookat: [0, 0, 0]\nup: [0, 1, 0]\nfov_angle: 50\n"
                                        "width: 30\nheight: 20\nnear: -1\nfar: -10\nlights: []\n"
                                        "meshes:\n  - {obj: tri.obj, ambient: [0, 0, 0], diffuse: [1, 1, 1], "
                                        "specular: [0, 0, 0], phong_exponent: 1}\n",
                                        (dir.path() / "seed.yaml").string());
    EXPECT_EQ(seed_yaml.settings.width, 30);
    EXPECT_FLOAT_EQ(seed_yaml.camera.near, 1.0f);
    EXPECT_FLOAT_EQ(seed_yaml.camera.far, 10.0f);
    // Top-level width in a raster scene is not a raster key.
    EXPECT_TRUE(scene_failure(std::string("width: 30\nmeshes:\n") + kTriangle).thrown);
}

// ---------------------------------------------------------------------------------------------------------------
// One test per class of bad input: InputError, right file, right line (and column), the problem named.

TEST(SceneLoader, rejectsYamlSyntaxError) {
    // Line 3 is indented one space: neither inside `image` nor at the top level.
    const Failure f = scene_failure("image:\n  width: 10\n height: 5\nmeshes: []\n");
    expect_failure_at(f, "scene.yaml", 3, 2, "YAML syntax error");
}

TEST(SceneLoader, rejectsJsonSyntaxErrorWithLineAndColumn) {
    // The second comma of line 3 ("    1,,") is column 7.
    const Failure f = scene_failure("{\n  \"meshes\": [\n    1,,\n  ]\n}\n", "scene.json");
    expect_failure_at(f, "scene.json", 3, 7, "JSON syntax error");
    EXPECT_TRUE(contains(f.message, "','"));
    EXPECT_FALSE(contains(f.message, "json.exception")) << "the message repeats nlohmann's prefix";
    // A trailing comma (valid YAML flow, invalid JSON) is caught by the strict check too: line 2, column 14 is '}'.
    const Failure trailing = scene_failure("{\"meshes\": [],\n \"image\": {},}\n", "scene.json");
    expect_failure_at(trailing, "scene.json", 2, 14, "JSON syntax error");
}

TEST(SceneLoader, rejectsUnknownKeyWithDidYouMean) {
    const Failure f = scene_failure(std::string("camera:\n  fow: 30\nmeshes:\n") + kTriangle);
    expect_failure_at(f, "scene.yaml", 2, 3, "unknown key 'fow'");
    EXPECT_TRUE(contains(f.message, "did you mean 'fov'"));
    // A key nowhere near a known one lists the choices instead.
    const Failure far_off = scene_failure(std::string("render:\n  quality: high\nmeshes:\n") + kTriangle);
    expect_failure_at(far_off, "scene.yaml", 2, 3, "unknown key 'quality'");
    EXPECT_TRUE(contains(far_off.message, "samples"));
}

TEST(SceneLoader, rejectsStringWhereNumberExpected) {
    const Failure f = scene_failure(std::string("image:\n  width: wide\nmeshes:\n") + kTriangle);
    expect_failure_at(f, "scene.yaml", 2, 10, "number");
    EXPECT_TRUE(contains(f.message, "width"));
    EXPECT_TRUE(contains(f.message, "wide"));
    // A list where a number is expected, and a string in a vector.
    expect_failure_at(scene_failure(std::string("camera:\n  fov: [45]\nmeshes:\n") + kTriangle), "scene.yaml", 2, 8,
                      "number");
    expect_failure_at(scene_failure(std::string("camera:\n  eye: [0, one, 5]\nmeshes:\n") + kTriangle), "scene.yaml",
                      2, 12, "number");
}

TEST(SceneLoader, rejectsNearNotPositive) {
    // "  near: " is 8 characters: the value is at column 9 of line 3.
    const Failure f = scene_failure(std::string("camera:\n  eye: [0, 0, 5]\n  near: -1\nmeshes:\n") + kTriangle);
    expect_failure_at(f, "scene.yaml", 3, 9, "near must be > 0");
    expect_failure_at(scene_failure(std::string("camera:\n  fov: 45\n  near: 0\nmeshes:\n") + kTriangle), "scene.yaml",
                      3, 9, "near must be > 0");
}

TEST(SceneLoader, rejectsNearNotBeforeFar) {
    const Failure f = scene_failure(std::string("camera:\n  near: 10\n  far: 5\nmeshes:\n") + kTriangle);
    expect_failure_at(f, "scene.yaml", 3, 8, "far");
    EXPECT_TRUE(contains(f.message, "near"));
    expect_failure_at(scene_failure(std::string("camera:\n  near: 10\n  far: 10\nmeshes:\n") + kTriangle), "scene.yaml",
                      3, 8, "far");
    // far left at its default 100: the near value is the one to blame.
    expect_failure_at(scene_failure(std::string("camera:\n  fov: 30\n  near: 200\nmeshes:\n") + kTriangle),
                      "scene.yaml", 3, 9, "far");
}

TEST(SceneLoader, rejectsFieldOfViewOutsideOpenInterval) {
    expect_failure_at(scene_failure(std::string("camera:\n  fov: 0\nmeshes:\n") + kTriangle), "scene.yaml", 2, 8,
                      "(0, 180)");
    expect_failure_at(scene_failure(std::string("camera:\n  near: 1\n  fov: 180\nmeshes:\n") + kTriangle), "scene.yaml",
                      3, 8, "(0, 180)");
    // Just inside the interval is fine.
    EXPECT_NO_THROW(parse_scene(std::string("camera:\n  fov: 179\nmeshes:\n") + kTriangle, "scene.yaml"));
    EXPECT_NO_THROW(parse_scene(std::string("camera:\n  fov: 0.5\nmeshes:\n") + kTriangle, "scene.yaml"));
}

TEST(SceneLoader, rejectsEyeEqualToTarget) {
    const Failure f = scene_failure(std::string("camera:\n  eye: [1, 2, 3]\n  target: [1, 2, 3]\nmeshes:\n") + kTriangle);
    expect_failure_at(f, "scene.yaml", 3, 11, "same point");
}

TEST(SceneLoader, rejectsUpParallelToViewDirection) {
    // Eye above the default target: the view direction is -y, parallel to up.
    const Failure f = scene_failure(std::string("camera:\n  eye: [0, 5, 0]\n  up: [0, 1, 0]\nmeshes:\n") + kTriangle);
    expect_failure_at(f, "scene.yaml", 3, 7, "parallel");
    expect_failure_at(scene_failure(std::string("camera:\n  eye: [0, 5, 0]\n  up: [0, -2, 0]\nmeshes:\n") + kTriangle),
                      "scene.yaml", 3, 7, "parallel");
    // A zero up vector is refused too.
    expect_failure_at(scene_failure(std::string("camera:\n  eye: [0, 0, 5]\n  up: [0, 0, 0]\nmeshes:\n") + kTriangle),
                      "scene.yaml", 3, 7, "up");
}

TEST(SceneLoader, rejectsFaceIndexOutOfRange) {
    // Column 20 of "    faces: [[0, 1, 3]]" is the 3.
    const Failure f = scene_failure("meshes:\n  - vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0]]\n    faces: [[0, 1, 3]]\n");
    expect_failure_at(f, "scene.yaml", 3, 20, "0..2");
    EXPECT_TRUE(contains(f.message, "3"));
    expect_failure_at(scene_failure("meshes:\n  - vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0]]\n    faces: [[0, -1, 2]]\n"),
                      "scene.yaml", 3, 17, "0..2");
}

TEST(SceneLoader, rejectsNonFiniteNumbers) {
    // "  background: [" is 15 characters: the first component is at column 16.
    for (const std::string value : {".nan", ".inf", "-.inf", ".NaN", "1e999", "-1e999"}) {
        const Failure f = scene_failure("image:\n  background: [" + value + ", 0, 0]\nmeshes:\n" + kTriangle);
        expect_failure_at(f, "scene.yaml", 2, 16, value);
    }
    // A float overflow in a vertex, and a NaN in a transform.
    expect_failure_at(scene_failure("meshes:\n  - vertices: [[0, 0, 0], [1, 0, 0], [0, 1e39, 0]]\n    faces: [[0, 1, 2]]\n"),
                      "scene.yaml", 2, 42, "1e39");
    expect_failure_at(scene_failure(std::string("meshes:\n") + kTriangle + "    transform:\n      - translate: [0, .nan, 0]\n"),
                      "scene.yaml", 5, 24, ".nan");
}

TEST(SceneLoader, rejectsResolutionOver16384) {
    expect_failure_at(scene_failure(std::string("image:\n  width: 16385\nmeshes:\n") + kTriangle), "scene.yaml", 2, 10,
                      "16384");
    expect_failure_at(scene_failure(std::string("image:\n  width: 10\n  height: 100000\nmeshes:\n") + kTriangle),
                      "scene.yaml", 3, 11, "16384");
    expect_failure_at(scene_failure(std::string("image:\n  width: 0\nmeshes:\n") + kTriangle), "scene.yaml", 2, 10, "1..");
    // 16384 x 1 is within every limit.
    EXPECT_NO_THROW(parse_scene(std::string("image: {width: 16384, height: 1}\nmeshes:\n") + kTriangle, "scene.yaml"));
}

TEST(SceneLoader, rejectsFrameBuffersOverMemoryCap) {
    // 16384 x 16384 x 16 samples x 28 bytes is far over 4 GiB; the sample count is the value to change.
    const Failure f =
        scene_failure(std::string("image: {width: 16384, height: 16384}\nrender:\n  samples: 16\nmeshes:\n") + kTriangle);
    expect_failure_at(f, "scene.yaml", 3, 12, "MiB");
    // Even one sample is 16384^2 x 32 bytes = 8 GiB: the image size is to blame.
    expect_failure_at(scene_failure(std::string("image: {width: 16384, height: 16384}\nmeshes:\n") + kTriangle),
                      "scene.yaml", 1, 8, "MiB");
    // README: 28 bytes per sample plus 4 per pixel, at most 4 GiB. At 16 samples that is 452 bytes a pixel:
    // 3082 x 3083 pixels need 4,294,816,312 bytes (fits), 3083 x 3083 need 4,296,209,828 (does not).
    EXPECT_NO_THROW(parse_scene(std::string("image: {width: 3082, height: 3083}\nrender: {samples: 16}\nmeshes:\n") +
                                    kTriangle,
                                "scene.yaml"));
    EXPECT_TRUE(scene_failure(std::string("image: {width: 3083, height: 3083}\nrender: {samples: 16}\nmeshes:\n") +
                              kTriangle)
                    .thrown);
    // README's example: 800 x 800 at 16 samples is fine.
    EXPECT_NO_THROW(parse_scene(std::string("image: {width: 800, height: 800}\nrender: {samples: 16}\nmeshes:\n") +
                                    kTriangle,
                                "scene.yaml"));
}

TEST(SceneLoader, rejectsSampleCountInvalidForPattern) {
    const Failure f = scene_failure(std::string("render:\n  pattern: standard\n  samples: 3\nmeshes:\n") + kTriangle);
    expect_failure_at(f, "scene.yaml", 3, 12, "3");
    EXPECT_TRUE(contains(f.message, "standard"));
    // Grids need a square count; the standard pattern has no 9.
    expect_failure_at(scene_failure(std::string("render:\n  samples: 8\n  pattern: grid\nmeshes:\n") + kTriangle),
                      "scene.yaml", 2, 12, "8");
    expect_failure_at(scene_failure(std::string("render:\n  samples: 9\nmeshes:\n") + kTriangle), "scene.yaml", 2, 12,
                      "9");
    for (const char* ok : {"{samples: 1}", "{samples: 2}", "{samples: 4}", "{samples: 8}", "{samples: 16}",
                           "{samples: 9, pattern: grid}", "{samples: 16, pattern: grid}"})
        EXPECT_NO_THROW(parse_scene(std::string("render: ") + ok + "\nmeshes:\n" + kTriangle, "scene.yaml")) << ok;
}

TEST(SceneLoader, rejectsMissingMeshFileNamingSceneLineAndMeshPath) {
    TempDir dir;
    const std::string name = (dir.path() / "scene.yaml").string();
    const Failure f = scene_failure(std::string("meshes:\n") + kTriangle + "  - file: models/nothere.obj\n", name);
    // "  - file: " is 10 characters: the path value is at column 11 of line 4.
    expect_failure_at(f, name, 4, 11, "models/nothere.obj");
    EXPECT_TRUE(contains(f.message, (dir.path() / "models/nothere.obj").string()));
}

TEST(SceneLoader, rejectsTruncatedObj) {
    TempDir dir;
    // The file ends in the middle of its third vertex.
    dir.write("cut.obj", "v 0 0 0\nv 1 0 0\nv 0 1");
    const std::string name = (dir.path() / "scene.yaml").string();
    const Failure f = scene_failure("meshes:\n  - file: cut.obj\n", name);
    expect_failure_at(f, name, 2, 11, "cut.obj");
    EXPECT_TRUE(contains(f.message, "cut.obj:3:"));  // the OBJ's own line
    // Truncated inside a face line.
    dir.write("cut2.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\nf 2 4");
    const Failure face = scene_failure("meshes:\n  - file: cut2.obj\n", name);
    expect_failure_at(face, name, 2, 11, "cut2.obj");
    EXPECT_TRUE(contains(face.message, "cut2.obj:6:"));
}

TEST(SceneLoader, rejectsNestingDeeperThan64Levels) {
    const std::string deep = std::string(65, '[') + std::string(65, ']');
    const Failure f = scene_failure("image: {width: 10}\nmeshes: " + deep + "\n");
    expect_failure_at(f, "scene.yaml", 2, 0, "nesting");
    EXPECT_TRUE(contains(f.message, "64"));
    // 64 levels are parsed (and then refused for what they contain, not for their depth).
    const Failure at_limit = scene_failure("image: {width: 10}\nmeshes: " + std::string(64, '[') + std::string(64, ']') + "\n");
    ASSERT_TRUE(at_limit.thrown);
    EXPECT_FALSE(contains(at_limit.message, "nesting"));
    // Deep block nesting (no brackets) is refused cleanly too, without exhausting the stack.
    std::string block;
    for (int i = 0; i < 10000; ++i) block += "- ";
    const Failure blocks = scene_failure(block + "x\n");
    ASSERT_TRUE(blocks.thrown);
    EXPECT_EQ(blocks.line, 1);
    EXPECT_TRUE(contains(blocks.message, "nesting"));
    // Brackets inside quoted strings and comments do not count.
    EXPECT_NO_THROW(parse_scene("# " + deep + "\nimage: {background: 0}\nmeshes:\n" + kTriangle, "scene.yaml"));
}

TEST(SceneLoader, rejectsEmptyFile) {
    expect_failure_at(scene_failure(""), "scene.yaml", 1, 1, "empty");
    expect_failure_at(scene_failure("\n\n   \n"), "scene.yaml", 1, 1, "empty");
    expect_failure_at(scene_failure("# just a comment\n"), "scene.yaml", 1, 1, "empty");
}

TEST(SceneLoader, rejectsNonMapDocument) {
    expect_failure_at(scene_failure("- 1\n- 2\n"), "scene.yaml", 1, 1, "map");
}

}  // namespace
