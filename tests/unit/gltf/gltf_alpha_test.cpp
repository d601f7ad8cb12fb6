// glTF alpha modes with a base colour texture: BLEND and MASK read the image's alpha (its factor's alpha becomes the
// material's opacity, MASK's cut-off the material's), OPAQUE and an image without alpha read none, a cut-out whose
// factor is below its cut-off is cut away, and a cut-off that is not a number at least 0 is refused by its path.
#include <fstream>
#include <iterator>

#include <gtest/gtest.h>

#include "raster/gltf/gltf_scene.h"
#include "tests/support/alpha_textures.h"
#include "tests/support/gltf_builder.h"

namespace raster {
namespace {

using test_support::GltfBuilder;
using test_support::tga_rgba;

// One textured triangle whose material has alpha mode `mode`, base colour factor alpha `alpha` and `more` fields,
// textured by `image`.
GltfBuilder textured(const std::string& mode, double alpha, const std::string& image,
                     const nlohmann::json& more = nlohmann::json::object()) {
    GltfBuilder b = GltfBuilder::one_triangle();
    nlohmann::json& primitive = b.document["meshes"][0]["primitives"][0];
    primitive["attributes"]["TEXCOORD_0"] = b.accessor(std::vector<float>{0, 0, 1, 0, 0, 1}, "VEC2", 5126);
    primitive["material"] = 0;
    nlohmann::json material = {{"alphaMode", mode},
                               {"pbrMetallicRoughness", {{"baseColorFactor", {1, 1, 1, alpha}}, {"baseColorTexture", {{"index", 0}}}}}};
    material.update(more);
    b.document["materials"] = {material};
    b.document["textures"] = {{{"source", b.image(image)}}};
    return b;
}

const std::string kRgba = tga_rgba(2, 1, {{10, 20, 30, 0}, {40, 50, 60, 102}});
// The corpus checker: an RGB PNG, without alpha.
std::string rgb_png() {
    std::ifstream png(std::string(RASTER_SOURCE_DIR) + "/corpus/textures/checker.png", std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(png)), std::istreambuf_iterator<char>());
}

TEST(GltfAlpha, blendReadsTheImagesAlphaAndTakesTheFactorsAlphaAsOpacity) {
    const Scene scene = test_support::read_built(textured("BLEND", 0.8, kRgba));
    const Material& m = scene.meshes.at(0).material;
    ASSERT_TRUE(m.texture);
    EXPECT_TRUE(m.texture->reads_alpha);
    EXPECT_FLOAT_EQ(m.opacity, 0.8f);
    EXPECT_FALSE(m.alpha_cutoff);
    ASSERT_TRUE(m.texture->alpha_texture);
    EXPECT_EQ(m.texture->alpha_texture->levels[0].at(0, 0), glm::vec3(0.0f));
    EXPECT_EQ(m.texture->alpha_texture->levels[0].at(1, 0), glm::vec3(102.0f / 255.0f));
    EXPECT_EQ(m.texture->texture->levels[0].at(1, 0), glm::vec3(40.0f, 50.0f, 60.0f) / 255.0f);
}

TEST(GltfAlpha, maskKeepsItsCutOffAndFactorForTheTexelsToMeet) {
    const Scene scene = test_support::read_built(textured("MASK", 0.9, kRgba, {{"alphaCutoff", 0.25}}));
    const Material& m = scene.meshes.at(0).material;
    ASSERT_TRUE(m.texture);
    EXPECT_TRUE(m.texture->reads_alpha);
    EXPECT_FLOAT_EQ(m.opacity, 0.9f);
    ASSERT_TRUE(m.alpha_cutoff);
    EXPECT_FLOAT_EQ(*m.alpha_cutoff, 0.25f);
}

TEST(GltfAlpha, aMaskWhoseFactorIsBelowItsCutOffIsCutAwayWhateverItsTexels) {
    // Its only triangle cut away, the model has nothing left to draw.
    EXPECT_EQ(test_support::read_error(textured("MASK", 0.2, kRgba, {{"alphaCutoff", 0.25}})),
              "/scenes: the scene places no triangles to draw");
    EXPECT_EQ(test_support::read_error(textured("MASK", 0.25, kRgba, {{"alphaCutoff", 0.25}})), "");
}

TEST(GltfAlpha, opaqueAndAnImageWithoutAlphaReadNone) {
    const Scene opaque = test_support::read_built(textured("OPAQUE", 0.5, kRgba));
    ASSERT_TRUE(opaque.meshes.at(0).material.texture);
    EXPECT_FALSE(opaque.meshes[0].material.texture->reads_alpha);
    EXPECT_FALSE(opaque.meshes[0].material.texture->alpha_texture);
    EXPECT_FLOAT_EQ(opaque.meshes[0].material.opacity, 1.0f);
    const Scene rgb = test_support::read_built(textured("MASK", 0.9, rgb_png(), {{"alphaCutoff", 0.5}}));
    ASSERT_TRUE(rgb.meshes.at(0).material.texture);
    EXPECT_FALSE(rgb.meshes[0].material.texture->reads_alpha);
    EXPECT_FALSE(rgb.meshes[0].material.alpha_cutoff);
    EXPECT_FLOAT_EQ(rgb.meshes[0].material.opacity, 1.0f);  // kept whole, and opaque
}

TEST(GltfAlpha, aCutOffThatIsNotANumberAtLeastZeroIsRefusedByItsPath) {
    EXPECT_EQ(test_support::read_error(textured("MASK", 1.0, kRgba, {{"alphaCutoff", -0.5}})),
              "/materials/0/alphaCutoff: must be a finite number at least 0");
}

}  // namespace
}  // namespace raster
