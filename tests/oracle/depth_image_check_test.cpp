// The depth image check: a file that follows the written definition passes; a byte off by one, rows flipped, the
// farthest sample kept instead of the nearest, or a file of another size, each fail at the pixels they change.
#include "oracle/compare/depth_image_check.h"

#include <vector>

#include <gtest/gtest.h>

#include "raster/core/conventions.h"

namespace raster::oracle {
namespace {

// A 3 x 2 frame of 2 samples a pixel: depths 1 (nearest), 4 (farthest) and 2, one pixel empty, one pixel with two
// surfaces (2 and 4: its nearest is 2).
struct Frame {
    std::vector<uint32_t> triangle{0, 0, 1, 1, 2, 2, kNoTriangle, kNoTriangle, 3, 4, 2, kNoTriangle};
    std::vector<glm::vec3> bary = std::vector<glm::vec3>(12, glm::vec3(1.0f / 3.0f));
    std::vector<float> depth{1, 1, 4, 4, 2, 2, 0, 0, 2, 4, 2, 0};
    RasterSamples samples() const { return {3, 2, 2, triangle.data(), bary.data(), depth.data()}; }
};

// The bytes by hand: 255 - 223 (d - 1) / 3: d = 1 -> 255, d = 4 -> 32, d = 2 -> 180.67 -> 181; empty -> 0.
const std::vector<uint8_t> kExpected{255, 32, 181, 0, 181, 181};

RasterPixels grey(const std::vector<uint8_t>& bytes, int width = 3, int height = 2) {
    return {width, height, 1, bytes.data()};
}

TEST(DepthImageCheck, passesTheDefinitionsBytesWorkedOutByHand) {
    const Frame frame;
    const DepthImageCheck check = check_depth_image(frame.samples(), grey(kExpected));
    EXPECT_EQ(check.pixels, 6u);
    EXPECT_EQ(check.genuine, 0u);
    EXPECT_EQ(check.max_difference, 0);
}

TEST(DepthImageCheck, failsAByteOffByOneAndNamesIt) {
    const Frame frame;
    std::vector<uint8_t> bytes = kExpected;
    bytes[2] = 180;
    const DepthImageCheck check = check_depth_image(frame.samples(), grey(bytes));
    EXPECT_EQ(check.genuine, 1u);
    ASSERT_EQ(check.first.size(), 1u);
    EXPECT_EQ(check.first[0].x, 2);
    EXPECT_EQ(check.first[0].y, 0);
    EXPECT_EQ(check.first[0].lo, 181);
    EXPECT_EQ(check.max_difference, 1);
}

TEST(DepthImageCheck, failsRowsFlippedTheFarthestSampleKeptAndAFileOfAnotherSize) {
    const Frame frame;
    const std::vector<uint8_t> flipped{0, 181, 181, 255, 32, 181};
    EXPECT_EQ(check_depth_image(frame.samples(), grey(flipped)).genuine, 4u);
    std::vector<uint8_t> farthest = kExpected;
    farthest[4] = 32;  // pixel (1, 1) shows 2 and 4: 4 is the farthest
    EXPECT_EQ(check_depth_image(frame.samples(), grey(farthest)).genuine, 1u);
    EXPECT_EQ(check_depth_image(frame.samples(), grey(kExpected, 2, 3)).genuine, 6u);
    EXPECT_EQ(check_depth_image(frame.samples(), RasterPixels{}).genuine, 6u);
}

}  // namespace
}  // namespace raster::oracle
