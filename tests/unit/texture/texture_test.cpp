// Texture images: decoding (values, grey, limits, errors) and the mip chain's sizes and weights, against
// hand-computed values.
#include "raster/texture/texture.h"

#include <string>

#include <gtest/gtest.h>

#include "raster/core/errors.h"
#include "tests/support/alpha_textures.h"

namespace raster {
namespace {

std::string ppm(int width, int height, const std::string& bytes) {
    return "P6\n" + std::to_string(width) + " " + std::to_string(height) + "\n255\n" + bytes;
}

TEST(TextureDecode, aTexelIsItsByteOver255WithRowZeroAtTheTop) {
    const Texture t = decode_texture(ppm(2, 1, std::string("\xff\x00\x80\x01\x02\x03", 6)), "two.ppm");
    ASSERT_EQ(t.levels.size(), 1u);
    ASSERT_EQ(t.levels[0].width, 2);
    EXPECT_EQ(t.levels[0].at(0, 0), glm::vec3(1.0f, 0.0f, 128.0f / 255.0f));
    EXPECT_EQ(t.levels[0].at(1, 0), glm::vec3(1.0f, 2.0f, 3.0f) / 255.0f);
    const Texture tall = decode_texture(ppm(1, 2, std::string("\x0a\x0a\x0a\x14\x14\x14", 6)), "tall.ppm");
    EXPECT_EQ(tall.levels[0].at(0, 0), glm::vec3(10.0f / 255.0f));  // the file's first row
}

TEST(TextureDecode, greyIsReplicatedToRgb) {
    const Texture t = decode_texture("P5\n1 1\n255\n\x33", "grey.pgm");
    EXPECT_EQ(t.levels[0].at(0, 0), glm::vec3(51.0f / 255.0f));
}

TEST(TextureDecode, alphaIsTheLastChannelOverItsFullScaleInEveryComponentAndOneWithoutIt) {
    const std::string rgba = test_support::tga_rgba(2, 1, {{10, 20, 30, 0}, {40, 50, 60, 128}});
    EXPECT_TRUE(image_has_alpha(rgba));
    const Texture alpha = decode_texture(rgba, "two.tga", TextureChannels::alpha);
    EXPECT_EQ(alpha.levels[0].at(0, 0), glm::vec3(0.0f));
    EXPECT_EQ(alpha.levels[0].at(1, 0), glm::vec3(128.0f / 255.0f));
    EXPECT_EQ(decode_texture(rgba, "two.tga").levels[0].at(1, 0), glm::vec3(40.0f, 50.0f, 60.0f) / 255.0f);
    const std::string rgb = ppm(1, 1, std::string("\x01\x02\x03", 3));
    EXPECT_FALSE(image_has_alpha(rgb));
    EXPECT_FALSE(image_has_alpha("not an image"));
    EXPECT_EQ(decode_texture(rgb, "one.ppm", TextureChannels::alpha).levels[0].at(0, 0), glm::vec3(1.0f));
    // Grey + alpha (a 16-bit grey TGA): the second channel, and grey in every colour component.
    std::string grey_alpha = std::string(18, '\0') + "\x10\x33";
    grey_alpha[2] = 3, grey_alpha[12] = 1, grey_alpha[14] = 1, grey_alpha[16] = 16, grey_alpha[17] = 0x28;
    EXPECT_TRUE(image_has_alpha(grey_alpha));
    EXPECT_EQ(decode_texture(grey_alpha, "ga.tga", TextureChannels::alpha).levels[0].at(0, 0), glm::vec3(51.0f / 255.0f));
    EXPECT_EQ(decode_texture(grey_alpha, "ga.tga").levels[0].at(0, 0), glm::vec3(16.0f / 255.0f));
}

TEST(TextureDecode, refusesWhatIsNotAnImageNamingTheFile) {
    try {
        decode_texture("not an image", "bad.png");
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_EQ(e.file(), "bad.png");
        EXPECT_NE(e.message().find("not an image"), std::string::npos) << e.message();
    }
}

TEST(TextureDecode, refusesAHeaderOverTheLimitsBeforeDecoding) {
    // 20000 x 20000 declared with no pixel data: refused by size, not by running out of bytes or memory.
    try {
        decode_texture("P6\n20000 20000\n255\n", "huge.ppm");
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_NE(e.message().find("over the limit"), std::string::npos) << e.message();
    }
}

TextureLevel level_of(int width, int height, float (*value)(int, int)) {
    TextureLevel level;
    level.width = width;
    level.height = height;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) level.texels.push_back(glm::vec3(value(x, y)));
    return level;
}

TEST(MipChain, levelSizesHalveDownToOneTexel) {
    EXPECT_EQ(mip_level_count(1, 1), 1);
    EXPECT_EQ(mip_level_count(256, 256), 9);
    EXPECT_EQ(mip_level_count(120, 90), 7);  // 120 60 30 15 7 3 1
    Texture t;
    t.levels.push_back(level_of(5, 3, [](int, int) { return 0.5f; }));
    build_mip_chain(t);
    ASSERT_EQ(t.levels.size(), 3u);
    EXPECT_EQ(t.levels[1].width, 2);
    EXPECT_EQ(t.levels[1].height, 1);
    EXPECT_EQ(t.levels[2].width, 1);
}

TEST(MipChain, aPowerOfTwoLevelIsTheMeanOfEach2x2Block) {
    const TextureLevel next = downsample(level_of(2, 2, [](int x, int y) { return float(x + 2 * y); }));
    ASSERT_EQ(next.texels.size(), 1u);
    EXPECT_FLOAT_EQ(next.texels[0].x, 1.5f);  // (0 + 1 + 2 + 3) / 4
}

TEST(MipChain, anOddSizeWeighsTheTexelItSplitsByHalf) {
    // 3 -> 1 wide: the one texel spans all three source texels; 5 -> 2: texel 0 spans [0, 2.5).
    const TextureLevel three = downsample(level_of(3, 1, [](int x, int) { return float(x); }));
    EXPECT_FLOAT_EQ(three.texels[0].x, 1.0f);
    const TextureLevel five = downsample(level_of(5, 1, [](int x, int) { return float(x * x); }));
    ASSERT_EQ(five.width, 2);
    EXPECT_FLOAT_EQ(five.texels[0].x, (0.0f + 1.0f + 0.5f * 4.0f) / 2.5f);
    EXPECT_FLOAT_EQ(five.texels[1].x, (0.5f * 4.0f + 9.0f + 16.0f) / 2.5f);
}

}  // namespace
}  // namespace raster
