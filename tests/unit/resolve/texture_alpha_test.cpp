// Texture alpha in the transparency pass: a blended pane's opacity is its material's times the texel's alpha, a
// cut-out is the texel's colour where that reaches the cut-off and the background elsewhere, MSAA evaluates both once
// per pixel, and a texture that reads alpha sends its triangles to the transparency pass and out of the shadow maps'.
#include <cmath>

#include <gtest/gtest.h>

#include "raster/frame/render.h"
#include "raster/geometry/front_end.h"
#include "tests/support/alpha_textures.h"

namespace raster {
namespace {

using test_support::alpha_textured_pane;
using test_support::tga_rgba;

// Two texels: the left half of the pane a quarter opaque (alpha 64), the right half opaque.
const std::string kImage = tga_rgba(2, 1, {{200, 40, 40, 64}, {40, 200, 40, 255}});
const glm::vec3 kBackground(0.2f, 0.4f, 0.6f);

Scene pane_scene(SceneMesh pane, int samples = 1, bool msaa = false) {
    Scene scene;
    scene.settings.width = scene.settings.height = 32;
    scene.settings.samples = samples;
    scene.settings.msaa = msaa;
    scene.settings.shading = ShadingMode::unlit;
    scene.settings.background = kBackground;
    scene.meshes = {std::move(pane)};
    return scene;
}

int byte_of(double v) { return static_cast<int>(std::floor(std::clamp(v, 0.0, 1.0) * 255.0 + 0.5)); }

// The bytes a blend of opacity a of texel colour `rgb` (bytes) over the background gives, by the blending formula.
void expect_blend(const uint8_t* pixel, double a, const glm::ivec3& rgb) {
    for (int c = 0; c < 3; ++c) EXPECT_EQ(pixel[c], byte_of(a * rgb[c] / 255.0 + (1.0 - a) * kBackground[c])) << c;
}

RenderResult draw(const Scene& scene) {
    RenderOptions options;
    options.threads = 2;
    return render(scene, options);
}

TEST(TextureAlpha, aBlendedPanesOpacityIsItsMaterialsTimesTheTexelsAlpha) {
    for (const auto& [samples, msaa] : {std::pair{1, false}, std::pair{4, false}, std::pair{4, true}}) {
        const RenderResult result = draw(pane_scene(alpha_textured_pane(3.0, 1.0, kImage, 0.6f), samples, msaa));
        expect_blend(result.image.at(9, 16), 0.6 * 64.0 / 255.0, {200, 40, 40});  // the left texel
        expect_blend(result.image.at(22, 16), 0.6, {40, 200, 40});                // the right texel
        expect_blend(result.image.at(0, 0), 0.0, {0, 0, 0});                      // outside the pane
    }
}

TEST(TextureAlpha, aCutOutShowsItsTexelWhereTheAlphaReachesTheCutOffAndTheBackgroundElsewhere) {
    // 0.6 x 64/255 = 0.15 is below the cut-off 0.3; 0.6 x 1 is above it, and then the surface is opaque.
    for (const auto& [samples, msaa] : {std::pair{1, false}, std::pair{4, true}}) {
        const RenderResult result = draw(pane_scene(alpha_textured_pane(3.0, 1.0, kImage, 0.6f, 0.3f), samples, msaa));
        expect_blend(result.image.at(9, 16), 0.0, {0, 0, 0});
        expect_blend(result.image.at(22, 16), 1.0, {40, 200, 40});
    }
    // With the cut-off above 0.6 nothing is left.
    const RenderResult none = draw(pane_scene(alpha_textured_pane(3.0, 1.0, kImage, 0.6f, 0.61f)));
    expect_blend(none.image.at(22, 16), 0.0, {0, 0, 0});
}

TEST(TextureAlpha, aCutOutInTheWeightedModeKeepsItsTexelsToo) {
    Scene scene = pane_scene(alpha_textured_pane(3.0, 1.0, kImage, 0.6f, 0.3f));
    scene.settings.transparency.mode = TransparencyMode::weighted;
    const RenderResult result = draw(scene);
    expect_blend(result.image.at(9, 16), 0.0, {0, 0, 0});
    expect_blend(result.image.at(22, 16), 1.0, {40, 200, 40});
}

TEST(TextureAlpha, aTextureThatReadsAlphaMakesItsTrianglesTransparent) {
    Scene scene = pane_scene(alpha_textured_pane(3.0, 1.0, kImage, 1.0f));
    EXPECT_TRUE(has_transparency(scene));
    EXPECT_EQ(transparent_triangles(scene), (std::vector<uint8_t>{1, 1}));
    scene.meshes[0].material.texture->reads_alpha = false;
    EXPECT_FALSE(has_transparency(scene));
    EXPECT_TRUE(transparent_triangles(scene).empty());
}

}  // namespace
}  // namespace raster
