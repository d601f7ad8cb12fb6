// KHR_texture_transform: the base colour texture's offset, rotation and scale move the texture coordinates as they
// are read (uv' = T R S uv in glTF's texture space, then v turned up); a texCoord other than 0 leaves the texture
// out; a malformed transform is refused naming its JSON path.
#include <cmath>
#include <fstream>
#include <iterator>

#include <gtest/gtest.h>

#include "raster/compat/scene_loader.h"
#include "raster/core/errors.h"
#include "raster/gltf/gltf_material.h"
#include "tests/support/gltf_builder.h"
#include "tests/support/temp_dir.h"

namespace raster {
namespace {

using test_support::GltfBuilder;
using test_support::TempDir;

// One triangle with texture coordinates `uvs` ((0, 0), (1, 0), (0, 1) unless given), textured by the corpus checker
// with `transform` as its KHR_texture_transform, written into `dir` beside the image and loaded.
Scene load_with_transform(TempDir& dir, const nlohmann::json& transform,
                          const std::vector<float>& uvs = {0, 0, 1, 0, 0, 1}) {
    std::ifstream png(std::string(RASTER_SOURCE_DIR) + "/corpus/textures/checker.png", std::ios::binary);
    dir.write("checker.png", std::string((std::istreambuf_iterator<char>(png)), std::istreambuf_iterator<char>()));
    GltfBuilder b = GltfBuilder::one_triangle();
    nlohmann::json& primitive = b.document["meshes"][0]["primitives"][0];
    primitive["attributes"]["TEXCOORD_0"] = b.accessor(uvs, "VEC2", 5126);
    primitive["material"] = 0;
    b.document["materials"] = {{{"pbrMetallicRoughness",
                                 {{"baseColorTexture", {{"index", 0}, {"extensions", {{"KHR_texture_transform", transform}}}}}}}}};
    b.document["textures"] = {{{"source", 0}}};
    b.document["images"] = {{{"uri", "checker.png"}}};
    b.document["extensionsUsed"] = {"KHR_texture_transform"};
    return load_scene(dir.write("model.gltf", b.text()));
}

void expect_uv(const glm::vec2& uv, double u, double v) {
    EXPECT_NEAR(uv.x, u, 1e-6);
    EXPECT_NEAR(uv.y, v, 1e-6);
}

TEST(GltfTextureTransform, offsetRotationAndScaleMoveTheCoordinatesBeforeVTurnsUp) {
    TempDir dir;
    // Scale 2, a quarter turn, offset (0.5, 0): (u, v) -> (2u, 2v) -> (-2v, 2u) -> (0.5 - 2v, 2u), then v' = 1 - v.
    const Scene scene =
        load_with_transform(dir, {{"offset", {0.5, 0}}, {"rotation", std::acos(-1.0) / 2}, {"scale", {2, 2}}});
    ASSERT_EQ(scene.meshes.size(), 1u);
    ASSERT_TRUE(scene.meshes[0].material.texture);
    const TriangleUvs& corners = scene.meshes[0].data->corner_uvs.at(0);
    expect_uv(corners.uv[0], 0.5, 1.0);   // (0, 0) -> (0.5, 0)
    expect_uv(corners.uv[1], 0.5, -1.0);  // (1, 0) -> (0.5, 2)
    expect_uv(corners.uv[2], -1.5, 1.0);  // (0, 1) -> (-1.5, 0)
}

TEST(GltfTextureTransform, theExtensionsDefaultsLeaveTheCoordinatesAsTheyAre) {
    TempDir dir;
    const Scene scene = load_with_transform(dir, nlohmann::json::object());
    const TriangleUvs& corners = scene.meshes[0].data->corner_uvs.at(0);
    expect_uv(corners.uv[0], 0.0, 1.0);
    expect_uv(corners.uv[1], 1.0, 1.0);
    expect_uv(corners.uv[2], 0.0, 0.0);
}

TEST(GltfTextureTransform, anotherCoordinateSetLeavesTheTextureOut) {
    TempDir dir;
    const Scene scene = load_with_transform(dir, {{"texCoord", 1}});
    EXPECT_FALSE(scene.meshes[0].material.texture);
    EXPECT_TRUE(scene.meshes[0].data->corner_uvs.empty());
}

TEST(GltfTextureTransform, aMalformedTransformIsRefusedNamingItsPath) {
    const std::string at = "/materials/0/pbrMetallicRoughness/baseColorTexture/extensions/KHR_texture_transform/";
    const std::pair<nlohmann::json, std::string> cases[] = {
        {{{"offset", {1}}}, at + "offset: must be an array of 2 numbers"},
        {{{"scale", {1, "two"}}}, at + "scale/1: must be a number"},
        {{{"rotation", 1e300}}, at + "rotation: must be a finite number up to 1e30"},
        {{{"texCoord", -1}}, at + "texCoord: must be a texture coordinate set's number"},
        // Vertex 1's u of 3e38 doubled is past float's largest.
        {{{"scale", {2, 1}}}, "TEXCOORD_0: texture coordinate 1 leaves float's range"},
    };
    for (const auto& [transform, message] : cases) {
        TempDir dir;
        try {
            load_with_transform(dir, transform, {0, 0, 3e38f, 0, 0, 1});
            ADD_FAILURE() << "read " << transform.dump();
        } catch (const InputError& e) {
            EXPECT_NE(e.message().find(message), std::string::npos) << e.message();
        }
    }
}

}  // namespace
}  // namespace raster
