// Texture lookups: wrap modes, v pointing up, texel centres, bilinear weights and the level of detail, against
// values worked out by hand from the definitions in texture_sampler.h.
#include "raster/texture/texture_sampler.h"

#include <cmath>
#include <memory>

#include <gtest/gtest.h>

namespace raster {
namespace {

// A 4 x 2 level whose texel (x, y) holds x + 10 y.
TextureLevel numbered_level() {
    TextureLevel level;
    level.width = 4;
    level.height = 2;
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 4; ++x) level.texels.push_back(glm::vec3(float(x + 10 * y)));
    return level;
}

TEST(Wrap, repeatClampAndMirrorAsDocumented) {
    const int expect_repeat[] = {2, 3, 0, 1, 2, 3, 0, 1};   // i = -2 .. 5 on 4 texels
    const int expect_clamp[] = {0, 0, 0, 1, 2, 3, 3, 3};
    const int expect_mirror[] = {1, 0, 0, 1, 2, 3, 3, 2};
    for (int i = -2; i <= 5; ++i) {
        EXPECT_EQ(wrap_texel(i, 4, TextureWrap::repeat), expect_repeat[i + 2]) << i;
        EXPECT_EQ(wrap_texel(i, 4, TextureWrap::clamp), expect_clamp[i + 2]) << i;
        EXPECT_EQ(wrap_texel(i, 4, TextureWrap::mirror), expect_mirror[i + 2]) << i;
    }
    EXPECT_EQ(wrap_texel(-9, 4, TextureWrap::mirror), 0);  // -9 mod 8 = 7, in the mirrored copy: 8 - 1 - 7
}

TEST(Nearest, vPointsUpSoTheTopRowIsVNearOne) {
    const TextureLevel level = numbered_level();
    EXPECT_EQ(sample_nearest(level, {0.1f, 0.9f}, TextureWrap::repeat).x, 0.0f);   // top-left texel (0, 0)
    EXPECT_EQ(sample_nearest(level, {0.1f, 0.1f}, TextureWrap::repeat).x, 10.0f);  // bottom row is y = 1
    EXPECT_EQ(sample_nearest(level, {0.9f, 0.9f}, TextureWrap::repeat).x, 3.0f);
    EXPECT_EQ(sample_nearest(level, {-0.1f, 0.9f}, TextureWrap::repeat).x, 3.0f);  // u = -0.1 wraps to 0.9
}

TEST(Bilinear, aTexelCentreReadsTheTexelAndHalfwayReadsTheMean) {
    const TextureLevel level = numbered_level();
    // Texel (1, 0)'s centre: x = 1.5 -> u = 1.5 / 4; y = 0.5 -> v = 1 - 0.5 / 2.
    EXPECT_FLOAT_EQ(sample_bilinear(level, {1.5f / 4, 0.75f}, TextureWrap::clamp).x, 1.0f);
    // Between texels (1, 0) and (2, 0): x = 2.
    EXPECT_FLOAT_EQ(sample_bilinear(level, {2.0f / 4, 0.75f}, TextureWrap::clamp).x, 1.5f);
    // Between the rows at x = 1.5: y = 1 -> v = 0.5.
    EXPECT_FLOAT_EQ(sample_bilinear(level, {1.5f / 4, 0.5f}, TextureWrap::clamp).x, 6.0f);
    // At u = 0 under repeat the left neighbour is the last column: (0 + 3) / 2.
    EXPECT_FLOAT_EQ(sample_bilinear(level, {0.0f, 0.75f}, TextureWrap::repeat).x, 1.5f);
}

TEST(LevelOfDetail, isLog2OfTheLongerSideInTexels) {
    TextureBinding binding;
    TextureLevel level;
    level.width = 64;
    level.height = 16;
    EXPECT_FLOAT_EQ(texture_footprint(level, sampler_of(binding), {1.0f / 64, 0}, {0, 1.0f / 16}).lod, 0.0f);
    EXPECT_FLOAT_EQ(texture_footprint(level, sampler_of(binding), {4.0f / 64, 0}, {0, 1.0f / 16}).lod, 2.0f);
    EXPECT_FLOAT_EQ(texture_footprint(level, sampler_of(binding), {0, 0}, {3.0f / 64, 4.0f / 16}).lod, std::log2(5.0f));
    EXPECT_TRUE(std::isinf(texture_footprint(level, sampler_of(binding), {NAN, 0}, {0, 0}).lod));
}

TEST(LevelOfDetail, anisotropicSplitsTheLongSideIntoTaps) {
    TextureBinding binding;
    binding.filter = TextureFilter::anisotropic;
    binding.max_anisotropy = 4;
    TextureLevel level;
    level.width = level.height = 64;
    // 8 texels across x, 1 down y: ratio 8, capped at 4 taps, so each tap covers 2 texels: lod 1.
    const Footprint f = texture_footprint(level, sampler_of(binding), {8.0f / 64, 0}, {0, 1.0f / 64});
    EXPECT_EQ(f.taps, 4);
    EXPECT_FLOAT_EQ(f.lod, 1.0f);
    EXPECT_EQ(f.major_axis, glm::vec2(8.0f / 64, 0));
    // Ratio 2.5 rounds up to 3 taps.
    EXPECT_EQ(texture_footprint(level, sampler_of(binding), {0, 1.0f / 64}, {0, 2.5f / 64}).taps, 3);
}

TEST(Trilinear, blendsTheTwoLevelsAroundTheLevelOfDetail) {
    auto texture = std::make_shared<Texture>();
    TextureLevel fine, coarse;
    fine.width = fine.height = 2;
    fine.texels.assign(4, glm::vec3(1.0f));
    coarse.width = coarse.height = 1;
    coarse.texels.assign(1, glm::vec3(0.0f));
    texture->levels = {fine, coarse};
    EXPECT_FLOAT_EQ(sample_trilinear(*texture, {0.3f, 0.3f}, 0.25f, TextureWrap::repeat).x, 0.75f);
    EXPECT_FLOAT_EQ(sample_trilinear(*texture, {0.3f, 0.3f}, -3.0f, TextureWrap::repeat).x, 1.0f);  // magnified
    EXPECT_FLOAT_EQ(sample_trilinear(*texture, {0.3f, 0.3f}, 7.0f, TextureWrap::repeat).x, 0.0f);   // past the chain
}

}  // namespace
}  // namespace raster
