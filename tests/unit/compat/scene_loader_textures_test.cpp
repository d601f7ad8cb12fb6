// Scenes with textures and OBJ materials: the raster format's texture keys, an OBJ's usemtl parts from its MTL,
// seed 003 taking an OBJ's textures, uvs dropped where no material reads them, files that other tools read drawn
// with warnings (missing images and libraries, Windows separators, nameless materials), and, strictly, the errors
// naming the line.
#include <gtest/gtest.h>

#include "raster/core/errors.h"
#include "raster/compat/scene_loader.h"
#include "raster/texture/texture.h"
#include "tests/support/temp_dir.h"

namespace raster {
namespace {

namespace fs = std::filesystem;
using raster::test_support::TempDir;

const std::string kPpm2x2 = std::string("P6\n2 2\n255\n") + std::string(12, '\x80');

const char* kQuadObj = "mtllib quad.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
                       "usemtl plain\nf 1/1 2/2 3/3\nusemtl wood\nf 1/1 3/3 4/4\n";

const char* kRasterScene = "camera: {eye: [0.5, 0.5, 3], target: [0.5, 0.5, 0]}\nmeshes:\n  - file: quad.obj\n";

TEST(SceneTextures, anObjsUsemtlRunsBecomeMaterialParts) {
    TempDir dir;
    dir.write("quad.obj", kQuadObj);
    dir.write("quad.mtl", "newmtl plain\nKd 0.5 0 0\nnewmtl wood\nKd 1 1 1\nmap_Kd tex/wood.ppm\n");
    dir.write("tex/wood.ppm", kPpm2x2);
    const Scene scene = load_scene(dir.write("scene.yaml", kRasterScene));
    const SceneMesh& mesh = scene.meshes.at(0);
    EXPECT_EQ(mesh.material.diffuse, glm::vec3(0.5f, 0, 0));
    EXPECT_FALSE(mesh.material.texture);
    ASSERT_EQ(mesh.parts.size(), 1u);
    EXPECT_EQ(mesh.parts[0].first_triangle, 1u);
    ASSERT_TRUE(mesh.parts[0].material.texture);
    const TextureBinding& binding = *mesh.parts[0].material.texture;
    EXPECT_EQ(binding.filter, TextureFilter::trilinear);
    EXPECT_EQ(binding.texture->levels.size(), 2u);  // 2x2 and 1x1: trilinear builds the chain
    EXPECT_EQ(&material_of(mesh, 1), &mesh.parts[0].material);
    EXPECT_EQ(&material_of(mesh, 0), &mesh.material);
    ASSERT_EQ(mesh.data->corner_uvs.size(), 2u);
    EXPECT_EQ(mesh.data->corner_uvs[1].uv[2], glm::vec2(0, 1));
}

TEST(SceneTextures, strictlyAMissingImageNamesTheMtlLine) {
    TempDir dir;
    dir.write("quad.obj", kQuadObj);
    dir.write("quad.mtl", "newmtl plain\nnewmtl wood\n\nmap_Kd nowhere.png\n");
    try {
        load_scene_file(dir.write("scene.yaml", kRasterScene), {true});
        FAIL() << "no error";
    } catch (const InputError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("quad.mtl:4"), std::string::npos) << what;
        EXPECT_NE(what.find("nowhere.png"), std::string::npos) << what;
    }
}

TEST(SceneTextures, strictlyAMissingLibraryNamesTheObjLine) {
    TempDir dir;
    dir.write("quad.obj", kQuadObj);
    try {
        load_scene_file(dir.write("scene.yaml", kRasterScene), {true});
        FAIL() << "no error";
    } catch (const InputError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("quad.obj:1"), std::string::npos) << what;
        EXPECT_NE(what.find("mtllib 'quad.mtl'"), std::string::npos) << what;
    }
}

// As assimp and viewers read them: a missing image leaves its material untextured, a missing library leaves its
// faces the default material, and the rest of the model is drawn as the files say.
TEST(SceneTextures, lenientlyAMissingImageOrLibraryIsDrawnWithoutIt) {
    TempDir dir;
    dir.write("quad.obj", kQuadObj);
    dir.write("quad.mtl", "newmtl plain\nKd 0.5 0 0\nnewmtl wood\nKd 0.25 0.25 0.25\nmap_Kd nowhere.png\n");
    const Scene untextured = load_scene(dir.write("scene.yaml", kRasterScene));
    const SceneMesh& mesh = untextured.meshes.at(0);
    EXPECT_EQ(mesh.material.diffuse, glm::vec3(0.5f, 0, 0));
    ASSERT_EQ(mesh.parts.size(), 1u);
    EXPECT_EQ(mesh.parts[0].material.diffuse, glm::vec3(0.25f));
    EXPECT_FALSE(mesh.parts[0].material.texture);
    EXPECT_TRUE(mesh.data->corner_uvs.empty());  // no material reads them now

    fs::remove(dir / "quad.mtl");
    const Scene bare = load_scene(dir / "scene.yaml");
    EXPECT_EQ(bare.meshes.at(0).material.diffuse, Material{}.diffuse);
    EXPECT_EQ(bare.meshes.at(0).parts.at(0).material.diffuse, Material{}.diffuse);
}

// A Windows exporter's `.\\tex\\wood.ppm`, and its `mtllib .\\quad.mtl`, name the files beside the model.
TEST(SceneTextures, backslashesInAnObjOrMtlNameAreSeparators) {
    TempDir dir;
    std::string obj = kQuadObj;
    obj.replace(0, std::string("mtllib quad.mtl").size(), "mtllib .\\quad.mtl");
    dir.write("quad.obj", obj);
    dir.write("quad.mtl", "newmtl plain\nnewmtl wood\nmap_Kd .\\tex\\wood.ppm\n");
    dir.write("tex/wood.ppm", kPpm2x2);
    const Scene scene = load_scene_file(dir.write("scene.yaml", kRasterScene), {true}).scene;
    ASSERT_EQ(scene.meshes.at(0).parts.size(), 1u);
    EXPECT_TRUE(scene.meshes.at(0).parts[0].material.texture);
}

TEST(SceneTextures, aNamelessNewmtlIsSkippedLenientlyAndRefusedStrictly) {
    TempDir dir;
    dir.write("quad.obj", kQuadObj);
    dir.write("quad.mtl", "newmtl\nKd 0 1 0\nnewmtl plain\nKd 0.5 0 0\nnewmtl wood\n");
    const Scene scene = load_scene(dir.write("scene.yaml", kRasterScene));
    EXPECT_EQ(scene.meshes.at(0).material.diffuse, glm::vec3(0.5f, 0, 0));
    EXPECT_THROW(load_scene_file(dir / "scene.yaml", {true}), InputError);
}

TEST(SceneTextures, rasterFormatTextureKeysAndInlineUvs) {
    TempDir dir;
    dir.write("t.ppm", kPpm2x2);
    const Scene scene = load_scene(dir.write(
        "scene.yaml", "meshes:\n  - vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0]]\n    faces: [[0, 1, 2]]\n"
                      "    uvs: [[0, 0], [2, 0], [0, 3]]\n"
                      "    material: {texture: t.ppm, filter: nearest, wrap: mirror}\n"));
    const TextureBinding& binding = *scene.meshes[0].material.texture;
    EXPECT_EQ(binding.filter, TextureFilter::nearest);
    EXPECT_EQ(binding.wrap, TextureWrap::mirror);
    EXPECT_EQ(binding.texture->levels.size(), 1u);  // nearest reads no mip chain, so none is built
    EXPECT_EQ(scene.meshes[0].data->corner_uvs.at(0).uv[2], glm::vec2(0, 3));
}

TEST(SceneTextures, anUntexturedSceneKeepsNoTextureCoordinates) {
    TempDir dir;
    dir.write("quad.obj", kQuadObj);
    dir.write("quad.mtl", "newmtl plain\nnewmtl wood\n");
    const Scene scene = load_scene(dir.write("scene.yaml", kRasterScene));
    EXPECT_TRUE(scene.meshes[0].data->corner_uvs.empty());
    EXPECT_FALSE(has_textures(scene));
}

TEST(SceneTextures, badTextureKeysNameTheirNode) {
    TempDir dir;
    dir.write("t.ppm", kPpm2x2);
    const std::string mesh = "meshes:\n  - vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0]]\n    faces: [[0, 1, 2]]\n";
    auto expect_error = [&](const std::string& material, const std::string& words) {
        try {
            load_scene(dir.write("scene.yaml", mesh + "    material: " + material + "\n"));
            FAIL() << "no error for " << material;
        } catch (const InputError& e) {
            EXPECT_EQ(e.line(), 4) << e.what();
            EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
        }
    };
    expect_error("{texture: t.ppm, filter: cubic}", "filter must be");
    expect_error("{texture: t.ppm, wrap: tile}", "wrap must be");
    expect_error("{filter: nearest}", "has no texture");
    expect_error("{texture: missing.png}", "missing.png");
}

TEST(SceneTextures, seed003TakesTheObjsTexturesWithTheScenesCoefficients) {
    TempDir dir;
    dir.write("quad.obj", kQuadObj);
    dir.write("quad.mtl", "newmtl plain\nKd 0.5 0 0\nnewmtl wood\nKd 0.1 0.1 0.1\nmap_Kd w.ppm\n");
    dir.write("w.ppm", kPpm2x2);
    const Scene scene = load_scene(dir.write(
        "scene.json", R"({"eye": [0.5, 0.5, 3], "lookat": [0.5, 0.5, 0], "up": [0, 1, 0], "fov_angle": 45,
                         "width": 32, "height": 32, "near": -0.1, "far": -10,
                         "meshes": [{"obj": "quad.obj", "ambient": [0.2, 0.2, 0.2], "diffuse": [0.6, 0.6, 0.6],
                                     "specular": [0, 0, 0], "phong_exponent": 8}]})"));
    const SceneMesh& mesh = scene.meshes.at(0);
    ASSERT_EQ(mesh.parts.size(), 1u);
    EXPECT_EQ(mesh.parts[0].material.diffuse, glm::vec3(0.6f));  // the scene's, not the MTL's
    EXPECT_TRUE(mesh.parts[0].material.texture);
    EXPECT_EQ(mesh.material.diffuse, glm::vec3(0.6f));
}

}  // namespace
}  // namespace raster
