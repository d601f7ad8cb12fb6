// The reduced-resolution upscale against its convention written out in double (tests/support/reference_upscale.h).
#include "raster/resolve/upscale.h"

#include <random>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "tests/support/reference_upscale.h"

namespace raster {
namespace {

Image random_image(std::mt19937& random, int width, int height, int channels) {
    Image image(width, height, channels);
    std::uniform_int_distribution<int> byte(0, 255);
    for (uint8_t& value : image.pixels) value = static_cast<uint8_t>(byte(random));
    return image;
}

TEST(Upscale, everyByteIsTheConventionsBlendOnRandomImagesOfEverySmallSize) {
    std::mt19937 random(20261208);
    std::vector<uint16_t> rows;
    for (int divisor : {2, 4})
        for (int channels : {1, 3, 4})
            for (int width = 1; width <= 9; ++width)
                for (int height = 1; height <= 6; ++height) {
                    const Image internal = random_image(random, width, height, channels);
                    Image out;
                    upscale_image(internal, divisor, 2, rows, out);
                    const Image expected = test::reference_upscale(internal, divisor);
                    ASSERT_EQ(out.width, expected.width);
                    ASSERT_EQ(out.height, expected.height);
                    ASSERT_EQ(out.channels, channels);
                    ASSERT_EQ(out.pixels, expected.pixels)
                        << width << "x" << height << " x" << channels << " at divisor " << divisor;
                }
}

TEST(Upscale, extremeBytesStayInRangeAndAConstantImageStaysConstant) {
    std::vector<uint16_t> rows;
    for (uint8_t value : {uint8_t{0}, uint8_t{1}, uint8_t{128}, uint8_t{254}, uint8_t{255}}) {
        Image internal(5, 3, 3);
        std::fill(internal.pixels.begin(), internal.pixels.end(), value);
        Image out;
        upscale_image(internal, 4, 1, rows, out);
        for (uint8_t byte : out.pixels) ASSERT_EQ(byte, value);
    }
    // A black-and-white checker: the largest sums the 16-bit lanes hold, and halves that round up.
    Image checker(6, 4, 3);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 6; ++x)
            for (int c = 0; c < 3; ++c) checker.at(x, y)[c] = (x + y) % 2 ? 255 : 0;
    for (int divisor : {2, 4}) {
        Image out;
        upscale_image(checker, divisor, 2, rows, out);
        EXPECT_EQ(out.pixels, test::reference_upscale(checker, divisor).pixels) << divisor;
    }
}

TEST(Upscale, divisorOneCopiesAndReusedBuffersGiveTheSameBytes) {
    std::mt19937 random(7);
    const Image small = random_image(random, 8, 5, 3);
    std::vector<uint16_t> rows;
    Image out;
    upscale_image(small, 1, 2, rows, out);
    EXPECT_EQ(out.pixels, small.pixels);
    const Image large = random_image(random, 40, 30, 4);
    upscale_image(large, 2, 2, rows, out);  // the buffers grow
    EXPECT_EQ(out.pixels, test::reference_upscale(large, 2).pixels);
    upscale_image(small, 2, 2, rows, out);  // and shrink: nothing left from the larger frame
    EXPECT_EQ(out.pixels, test::reference_upscale(small, 2).pixels);
}

// Images taller than a parallel task's band of rows (16), on 1, 2 and 3 threads: the bands meet without a seam.
TEST(Upscale, tallImagesSplitIntoBandsOnAnyThreadCountGiveTheSameBytes) {
    std::mt19937 random(11);
    std::vector<uint16_t> rows;
    for (int divisor : {2, 4}) {
        const Image tall = random_image(random, 7, 41, 3);
        const Image expected = test::reference_upscale(tall, divisor);
        for (int threads : {1, 2, 3}) {
            Image out;
            upscale_image(tall, divisor, threads, rows, out);
            EXPECT_EQ(out.pixels, expected.pixels) << divisor << " on " << threads << " threads";
        }
    }
}

TEST(Upscale, anotherDivisorOrChannelCountOrTheInputAsOutputIsRefused) {
    std::vector<uint16_t> rows;
    Image image(4, 4, 3), out;
    EXPECT_THROW(upscale_image(image, 3, 1, rows, out), std::invalid_argument);
    EXPECT_THROW(upscale_image(image, 0, 1, rows, out), std::invalid_argument);
    EXPECT_THROW(upscale_image(image, 2, 1, rows, image), std::invalid_argument);
    Image five(2, 2, 5);
    EXPECT_THROW(upscale_image(five, 2, 1, rows, out), std::invalid_argument);
}

}  // namespace
}  // namespace raster
