// Sample positions: the standard tables are Vulkan's, grids are regular, invalid counts are refused.
#include "raster/geometry/sample_pattern.h"

#include <set>

#include <gtest/gtest.h>

namespace raster {
namespace {

TEST(SamplePattern, standardFourIsVulkansTable) {
    // Vulkan primsrast.adoc, standard sample locations for 4 samples.
    const std::vector<glm::vec2> expected = {{0.375f, 0.125f}, {0.875f, 0.375f}, {0.125f, 0.625f}, {0.625f, 0.875f}};
    EXPECT_EQ(sample_offsets(4, SamplePattern::standard), expected);
    EXPECT_EQ(sample_offsets(1, SamplePattern::standard), std::vector<glm::vec2>{glm::vec2(0.5f, 0.5f)});
}

TEST(SamplePattern, standardPatternsAreDistinctSixteenthsInsideThePixel) {
    for (int samples : {1, 2, 4, 8, 16}) {
        const auto offsets = sample_offsets(samples, SamplePattern::standard);
        ASSERT_EQ(static_cast<int>(offsets.size()), samples);
        std::set<std::pair<float, float>> distinct;
        for (const auto& o : offsets) {
            EXPECT_GE(o.x, 0.0f);
            EXPECT_LT(o.x, 1.0f);
            EXPECT_EQ(o.x * 16.0f, std::floor(o.x * 16.0f));  // exact on a 1/16 grid
            EXPECT_EQ(o.y * 16.0f, std::floor(o.y * 16.0f));
            distinct.insert({o.x, o.y});
        }
        EXPECT_EQ(static_cast<int>(distinct.size()), samples);
    }
    // Every standard pattern averages to the pixel centre.
    for (int samples : {2, 4, 8, 16}) {
        glm::vec2 mean(0.0f);
        for (const auto& o : sample_offsets(samples, SamplePattern::standard)) mean += o / float(samples);
        EXPECT_NEAR(mean.x, 0.5f, 0.04f);
        EXPECT_NEAR(mean.y, 0.5f, 0.04f);
    }
}

TEST(SamplePattern, gridIsRowByRowAtCellCentres) {
    const auto offsets = sample_offsets(16, SamplePattern::grid);
    ASSERT_EQ(offsets.size(), 16u);
    EXPECT_EQ(offsets[0], glm::vec2(0.125f, 0.125f));
    EXPECT_EQ(offsets[1], glm::vec2(0.375f, 0.125f));
    EXPECT_EQ(offsets[4], glm::vec2(0.125f, 0.375f));
    EXPECT_EQ(offsets[15], glm::vec2(0.875f, 0.875f));
}

TEST(SamplePattern, invalidCountsAreRefusedWithAReason) {
    EXPECT_TRUE(sample_offsets(3, SamplePattern::standard).empty());
    EXPECT_NE(sample_count_error(3, SamplePattern::standard), "");
    EXPECT_NE(sample_count_error(8, SamplePattern::grid), "");  // not a square
    EXPECT_NE(sample_count_error(0, SamplePattern::grid), "");
    EXPECT_NE(sample_count_error(17 * 17, SamplePattern::grid), "");
    EXPECT_EQ(sample_count_error(9, SamplePattern::grid), "");
}

TEST(SamplePattern, fixedOffsetsAreExactForStandardAndStayInsideThePixel) {
    const auto fixed = fixed_sample_offsets(sample_offsets(16, SamplePattern::standard), 4);
    EXPECT_EQ(fixed.x[0], 9);  // 0.5625 * 16
    EXPECT_EQ(fixed.y[15], 0);
    // A 16 x 16 grid at 4 fractional bits rounds 15.5/16 up to 16: it must stay in the pixel.
    const auto grid = fixed_sample_offsets(sample_offsets(256, SamplePattern::grid), 4);
    for (int64_t x : grid.x) EXPECT_LT(x, 16);
}

}  // namespace
}  // namespace raster
