// The oracle's texture alpha on its own: a layer's opacity is the material's times the texel's alpha as the oracle
// decodes it, a cut-out's is 1 or 0 on either side of its cut-off and open ([0, 1]) where the product may fall on
// either, and a texture that reads alpha makes its triangles layers rather than opaque surfaces.
#include <gtest/gtest.h>

#include "oracle/reference/layer_caster.h"
#include "oracle/reference/scene_geometry.h"
#include "oracle/reference/shader.h"
#include "tests/support/alpha_textures.h"

namespace raster::oracle {
namespace {

using test_support::alpha_textured_pane;
using test_support::tga_rgba;

const std::string kImage = tga_rgba(2, 1, {{200, 40, 40, 64}, {40, 200, 40, 255}});

Scene pane_scene(std::optional<float> cutoff) {
    Scene scene;
    scene.settings.width = scene.settings.height = 32;
    scene.settings.shading = ShadingMode::unlit;
    scene.meshes = {alpha_textured_pane(3.0, 1.0, kImage, 0.6f, cutoff)};
    return scene;
}

// Triangle 0 has texture coordinates (0, 0), (1, 0), (1, 1): these barycentrics fall in the left and right texels.
const Interval3 kLeft(glm::dvec3(0.6, 0.3, 0.1)), kRight(glm::dvec3(0.1, 0.3, 0.6));

void expect_near(const Interval& got, double value) {
    EXPECT_LE(got.lo, value);
    EXPECT_GE(got.hi, value);
    EXPECT_LT(got.hi - got.lo, 1e-6);
}

TEST(TextureAlphaOracle, aLayersOpacityIsTheMaterialsTimesTheTexelsAlpha) {
    const Scene scene = pane_scene(std::nullopt);
    const OracleScene geometry = oracle_scene(scene);
    const OracleShader shader(scene, geometry);
    expect_near(shader.opacity(0, kLeft), 0.6f * 64.0 / 255.0);
    expect_near(shader.opacity(0, kRight), 0.6f);
}

TEST(TextureAlphaOracle, aCutOutIsOneOrZeroAwayFromItsCutOffAndOpenOnIt) {
    for (const auto& [cutoff, left, right] : {std::tuple{0.3f, 0.0, 1.0}, std::tuple{0.7f, 0.0, 0.0}, std::tuple{0.1f, 1.0, 1.0}}) {
        const Scene scene = pane_scene(cutoff);
        const OracleScene geometry = oracle_scene(scene);
        const OracleShader shader(scene, geometry);
        const Interval l = shader.opacity(0, kLeft), r = shader.opacity(0, kRight);
        EXPECT_EQ(l.lo, left) << cutoff;
        EXPECT_EQ(l.hi, left) << cutoff;
        EXPECT_EQ(r.lo, right) << cutoff;
        EXPECT_EQ(r.hi, right) << cutoff;
    }
    // The cut-off at the product itself: raster may land on either side.
    const Scene scene = pane_scene(static_cast<float>(0.6f * (64.0f / 255.0f)));
    const OracleScene geometry = oracle_scene(scene);
    const Interval open = OracleShader(scene, geometry).opacity(0, kLeft);
    EXPECT_EQ(open.lo, 0.0);
    EXPECT_EQ(open.hi, 1.0);
}

TEST(TextureAlphaOracle, aTextureThatReadsAlphaMakesItsTrianglesLayers) {
    Scene scene = pane_scene(std::nullopt);
    scene.meshes[0].material.opacity = 1.0f;  // opaque but for the texture's alpha
    EXPECT_TRUE(layered_material(scene.meshes[0].material));
    const OracleScene geometry = oracle_scene(scene);
    const SampleLayers layers = trace_layers(scene, geometry, OracleOptions{});
    EXPECT_FALSE(layers.hits.empty());
    scene.meshes[0].material.texture->reads_alpha = false;
    EXPECT_FALSE(layered_material(scene.meshes[0].material));
}

}  // namespace
}  // namespace raster::oracle
