// The inspector's evidence: exactly the pixels with a sample that is not "agree", each sample's class and both
// renderers' triangle, barycentrics and depth, and a cap that counts what it leaves out.
#include "harness/comparison/pixel_evidence.h"

#include <string>

#include <gtest/gtest.h>

#include "raster/compat/scene_loader.h"

namespace raster {
namespace {

const std::filesystem::path kSource = RASTER_SOURCE_DIR;

TEST(PixelEvidence, listsEveryPixelWithASampleThatIsNotAgreeAndWhatEachSideSawThere) {
    Scene scene = load_scene(kSource / "corpus/scenes/teapot.yaml");
    scene.settings.samples = 4;
    const harness::Comparison c = harness::compare_scene(scene, harness::ComparisonOptions{});
    size_t notable = 0;
    std::string first;
    for (int y = 0; y < c.height; ++y)
        for (int x = 0; x < c.width; ++x) {
            bool any = false;
            for (int s = 0; s < c.samples; ++s)
                any |= c.visibility.classes[c.raster.visibility.index(x, y, s)] != oracle::SampleClass::agree;
            if (any && first.empty()) first = std::to_string(x) + "," + std::to_string(y);
            notable += any;
        }
    ASSERT_GT(notable, 0u) << "the teapot at 4 samples has edge-band samples";
    const nlohmann::json evidence = harness::pixel_evidence(c);
    EXPECT_EQ(evidence["samples"], 4);
    EXPECT_EQ(evidence["listed"], notable);
    EXPECT_EQ(evidence["unlisted"], 0);
    EXPECT_EQ(evidence["pixels"].size(), notable);
    // The first such pixel, sample by sample, as each buffer holds it.
    const int x = std::stoi(first.substr(0, first.find(','))), y = std::stoi(first.substr(first.find(',') + 1));
    const nlohmann::json& samples = evidence["pixels"].at(first);
    ASSERT_EQ(samples.size(), 4u);
    for (int s = 0; s < 4; ++s) {
        const size_t i = c.raster.visibility.index(x, y, s);
        EXPECT_EQ(samples[s][0], oracle::to_string(c.visibility.classes[i]));
        EXPECT_EQ(samples[s][1].get<int64_t>(), c.raster.visibility.triangle[i] == kNoTriangle
                                                    ? -1 : int64_t(c.raster.visibility.triangle[i]));
        EXPECT_EQ(samples[s][2][1].get<float>(), c.raster.visibility.bary[i].y);
        EXPECT_EQ(samples[s][3].get<float>(), c.raster.visibility.view_depth[i]);
        EXPECT_EQ(samples[s][4].get<int64_t>(), c.oracle_visibility.triangle[i] == kNoTriangle
                                                    ? -1 : int64_t(c.oracle_visibility.triangle[i]));
        EXPECT_EQ(samples[s][6].get<float>(), c.oracle_visibility.view_depth[i]);
    }
    // Past the cap, the pixels are counted, not listed.
    const nlohmann::json capped = harness::pixel_evidence(c, 3);
    EXPECT_EQ(capped["listed"], 3);
    EXPECT_EQ(capped["unlisted"], notable - 3);
    EXPECT_EQ(capped["pixels"].size(), 3u);
    EXPECT_TRUE(capped["pixels"].contains(first));
}

}  // namespace
}  // namespace raster
