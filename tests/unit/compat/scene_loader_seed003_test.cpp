// Scene loader tests, the seed 003 course's JSON scenes, and how the loader tells the formats apart by content.
#include <filesystem>
#include <string>

#include <glm/vec3.hpp>
#include <gtest/gtest.h>

#include "tests/support/temp_dir.h"

#include "raster/core/errors.h"
#include "raster/compat/scene_loader.h"

namespace raster::scene_loader_tests {

// The document's key set, one key a line, with the mesh's obj path and the near and far values as written (the
// rejection table, scene_loader_errors_test.cpp, points into it by line and column).
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

}  // namespace raster::scene_loader_tests

namespace {

namespace fs = std::filesystem;
using raster::InputError;
using raster::parse_scene;
using raster::Scene;
using raster::scene_loader_tests::seed003_scene;
using raster::test_support::TempDir;

void expect_vec3(const glm::vec3& v, float x, float y, float z) {
    EXPECT_NEAR(v.x, x, 1e-5f);
    EXPECT_NEAR(v.y, y, 1e-5f);
    EXPECT_NEAR(v.z, z, 1e-5f);
}

const char* kTriangle = "  - vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0]]\n    faces: [[0, 1, 2]]\n";

// ---------------------------------------------------------------------------------------------------------------
// Seed 003 JSON scenes

// An OBJ triangle with normals that point away from the face normal (+z), so dropping them is observable.
const char* kObjWithNormals = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 1 0 0\nf 1//1 2//1 3//1\n";

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
    // docs: the document's default shading is per-fragment Blinn-Phong.
    EXPECT_EQ(scene.settings.shading, raster::ShadingMode::blinn_phong);
    ASSERT_EQ(scene.lights.size(), 1u);
    expect_vec3(scene.lights[0].position, 2, 3, 4);
    expect_vec3(scene.lights[0].color, 1, 0.5f, 0.25f);
    ASSERT_EQ(scene.meshes.size(), 1u);
    const raster::SceneMesh& mesh = scene.meshes[0];
    EXPECT_EQ(mesh.data->triangles.size(), 1u);
    expect_vec3(mesh.material.ambient, 0.1f, 0.2f, 0.3f);
    expect_vec3(mesh.material.diffuse, 0.4f, 0.5f, 0.6f);
    expect_vec3(mesh.material.specular, 0.7f, 0.8f, 0.9f);
    EXPECT_FLOAT_EQ(mesh.material.exponent, 12.0f);
}

// raster's extension of the document: a light's `shadows` key, off unless a light says so.
TEST(SceneLoader, seed003LightCastsShadowsOnlyWhenItSaysSo) {
    TempDir dir;
    dir.write("models/tri.obj", kObjWithNormals);
    std::string text = seed003_scene("models/tri.obj", "-0.5", "-50");
    EXPECT_FALSE(raster::load_scene(dir.write("plain.json", text)).lights.at(0).shadows);
    const std::string light = "\"color\": [1, 0.5, 0.25]}";
    text.replace(text.find(light), light.size(), "\"color\": [1, 0.5, 0.25], \"shadows\": true}");
    EXPECT_TRUE(raster::load_scene(dir.write("shadowed.json", text)).lights.at(0).shadows);
}

TEST(SceneLoader, seed003ObjPathIsRelativeToTheSceneFile) {
    TempDir dir;
    dir.write("deep/models/tri.obj", kObjWithNormals);
    const fs::path path = dir.write("deep/scene.json", seed003_scene("models/tri.obj", "-0.1", "-100"));
    EXPECT_EQ(raster::load_scene(path).meshes.at(0).data->triangles.size(), 1u);
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

TEST(SceneLoader, seed003DropsNormalsFromTheObj) {
    TempDir dir;
    dir.write("tri.obj", kObjWithNormals);
    const Scene scene = parse_scene(seed003_scene("tri.obj", "-0.1", "-100"), (dir.path() / "s.json").string());
    EXPECT_TRUE(scene.meshes.at(0).data->normals.empty());
    // The same OBJ in a raster scene keeps them.
    const Scene raster_scene = parse_scene("meshes:\n  - file: tri.obj\n", (dir.path() / "s.yaml").string());
    ASSERT_EQ(raster_scene.meshes.at(0).data->normals.size(), 3u);
    expect_vec3(raster_scene.meshes[0].data->normals[0], 1, 0, 0);
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
    EXPECT_NE(warnings.find("antialias"), std::string::npos) << warnings;
    EXPECT_NE(warnings.find("warning"), std::string::npos) << warnings;
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
    EXPECT_TRUE(seed.meshes.at(0).data->normals.empty());
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
    EXPECT_THROW(parse_scene(std::string("width: 30\nmeshes:\n") + kTriangle, "scene.yaml"), InputError);
}

}  // namespace
