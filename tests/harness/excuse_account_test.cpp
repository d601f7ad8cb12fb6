// The excuse accounting: each class counted in samples and in pixels from a comparison's classes, caps as shares,
// accounts summed; the colour intervals' width bins; and what each precision mode leaves unjudged in the verdict.
#include "harness/comparison/excuse_account.h"

#include <gtest/gtest.h>

#include "harness/comparison/judged_classes.h"

namespace raster::harness {
namespace {

using oracle::SampleClass;

// Two pixels of two samples: an edge-band sample in the first pixel, a depth tie and a facing sample in the second.
Comparison two_pixels() {
    Comparison c;
    c.width = 2;
    c.height = 1;
    c.samples = 2;
    c.visibility.classes = {SampleClass::edge_band, SampleClass::agree, SampleClass::depth_tie, SampleClass::facing};
    for (SampleClass k : c.visibility.classes) ++c.visibility.counts.by_class[static_cast<size_t>(k)];
    c.colour.png.wide = 1;
    c.shadows.edge_pixels = 1;
    return c;
}

const ExcuseLine& line(const ExcuseAccount& account, const std::string& name, const std::string& unit) {
    for (const ExcuseLine& l : account.lines)
        if (l.name == name && l.unit == unit) return l;
    throw std::runtime_error("no line " + name + " " + unit);
}

TEST(ExcuseAccount, countsEachClassInSamplesAndInPixelsWithAPixelCountedOncePerClass) {
    ExcuseCaps caps;
    caps.sample_share = caps.pixel_share = caps.wide_interval = caps.shadow_open = caps.layers_open = 1.0;
    const ExcuseAccount account = account_excuses(two_pixels(), caps);
    EXPECT_EQ(line(account, "edge_band", "samples").count, 1u);
    EXPECT_EQ(line(account, "edge_band", "samples").of, 4u);
    EXPECT_EQ(line(account, "edge_band", "pixels").count, 1u);
    EXPECT_EQ(line(account, "edge_band", "pixels").of, 2u);
    EXPECT_EQ(line(account, "depth_tie", "pixels").count, 1u);
    EXPECT_EQ(line(account, "facing", "pixels").count, 1u);
    EXPECT_EQ(line(account, "clip_boundary", "samples").count, 0u);
    EXPECT_EQ(line(account, "wide_interval", "pixels").count, 1u);
    EXPECT_EQ(line(account, "shadow_open", "pixels").count, 1u);
    EXPECT_TRUE(account.within());
    EXPECT_EQ(account.violations(), "");
}

TEST(ExcuseAccount, aClassOverItsShareIsNamedAndSummedAccountsAddUp) {
    ExcuseCaps caps;  // every share 0: any excuse is over
    caps.sample_share = 0.25;  // one sample in four is allowed, one pixel in two is not
    ExcuseAccount account = account_excuses(two_pixels(), caps);
    EXPECT_TRUE(line(account, "edge_band", "samples").within());
    EXPECT_FALSE(line(account, "edge_band", "pixels").within());
    EXPECT_FALSE(account.within());
    EXPECT_NE(account.violations().find("edge_band excused 1 of 2 pixels"), std::string::npos) << account.violations();
    EXPECT_EQ(account.violations().find("clip_boundary"), std::string::npos);
    account.add(account_excuses(two_pixels(), caps));
    EXPECT_EQ(line(account, "edge_band", "samples").count, 2u);
    EXPECT_EQ(line(account, "edge_band", "samples").of, 8u);
}

TEST(IntervalWidths, binsArePowersOfTwoUpToTheWholeRange) {
    const struct {
        int width, bin;
    } kCases[] = {{0, 0}, {1, 1}, {2, 2}, {3, 2}, {4, 3}, {31, 5}, {32, 6}, {127, 7}, {128, 8}, {255, 8}};
    for (const auto& c : kCases) EXPECT_EQ(oracle::IntervalWidths::bin(c.width), c.bin) << c.width;
    EXPECT_STREQ(oracle::IntervalWidths::label(2), "2-3");
    EXPECT_STREQ(oracle::IntervalWidths::label(8), "128-255");
}

TEST(JudgedClasses, eachModeBeyondTheModelLeavesWhatItMovesOutOfTheVerdict) {
    EXPECT_TRUE(judged_classes(PrecisionModes{}).unjudged.empty());
    PrecisionModes modes;
    modes.edges = EdgeArithmetic::float32;
    EXPECT_FALSE(judged_classes(modes).visibility);
    EXPECT_TRUE(judged_classes(modes).interpolation);
    modes = PrecisionModes{};
    modes.interpolation = Interpolation::affine;
    EXPECT_TRUE(judged_classes(modes).visibility);
    EXPECT_FALSE(judged_classes(modes).interpolation);
    modes.depth = DepthFormat::fixed24;
    modes.clipping = Clipping::guard_band;
    EXPECT_EQ(judged_classes(modes).unjudged.size(), 3u);

    Comparison c = two_pixels();
    c.visibility.counts.by_class[static_cast<size_t>(SampleClass::visibility)] = 5;
    c.visibility.counts.by_class[static_cast<size_t>(SampleClass::barycentrics)] = 2;
    c.colour.genuine_pixels = 3;
    c.depth.genuine_pixels = 1;
    EXPECT_EQ(c.genuine_total(), 11u);
    c.judged.visibility = false;
    EXPECT_EQ(c.genuine_total(), 6u);
    c.judged.interpolation = false;
    EXPECT_EQ(c.genuine_total(), 1u);  // the depth image is judged whatever the modes
    EXPECT_EQ(c.disagreements_total(), 11u);
}

}  // namespace
}  // namespace raster::harness
