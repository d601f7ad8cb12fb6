// The inspector's evidence: exactly the pixels that need explaining (a sample that is not "agree", a colour outside
// its bounds, a shadow or a transparent layer left open), each sample's class with its excuse and both renderers'
// triangle, barycentrics and depth, the pixel's bytes on both sides, and a cap that counts what it leaves out.
#include "harness/comparison/pixel_evidence.h"

#include <algorithm>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "harness/comparison/scene_comparison.h"
#include "raster/compat/scene_loader.h"

namespace raster {
namespace {

const std::filesystem::path kSource = RASTER_SOURCE_DIR;

harness::Comparison compared(const char* file, int samples, size_t evidence_pixels) {
    Scene scene = load_scene(kSource / file);
    scene.settings.samples = samples;
    harness::ComparisonOptions options;
    options.evidence_pixels = evidence_pixels;
    return harness::compare_scene(scene, options);
}

std::pair<int, int> pixel_of(const std::string& key) {
    return {std::stoi(key.substr(0, key.find(','))), std::stoi(key.substr(key.find(',') + 1))};
}

TEST(PixelEvidence, listsEveryPixelWithASampleThatIsNotAgreeAndWhatEachSideSawThere) {
    const harness::Comparison c = compared("corpus/scenes/teapot.yaml", 4, 20000);
    size_t notable = 0;
    std::string first;
    for (int y = 0; y < c.height; ++y)
        for (int x = 0; x < c.width; ++x) {
            bool any = c.colour.genuine[size_t(y) * size_t(c.width) + size_t(x)] != 0;
            for (int s = 0; s < c.samples; ++s)
                any |= c.visibility.classes[c.raster.visibility.index(x, y, s)] != oracle::SampleClass::agree;
            if (any && first.empty()) first = std::to_string(x) + "," + std::to_string(y);
            notable += any;
        }
    ASSERT_GT(notable, 0u) << "the teapot at 4 samples has edge-band samples";
    const nlohmann::json& evidence = c.evidence;
    EXPECT_EQ(evidence["samples"], 4);
    EXPECT_EQ(evidence["listed"], notable);
    EXPECT_EQ(evidence["unlisted"], 0);
    EXPECT_EQ(evidence["pixels"].size(), notable);
    // The first such pixel, sample by sample, as each buffer holds it, and its bytes as each image holds them.
    const auto [x, y] = pixel_of(first);
    const nlohmann::json& pixel = evidence["pixels"].at(first);
    const nlohmann::json& samples = pixel["samples"];
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
        EXPECT_FALSE(samples[s][7].get<std::string>().empty());
        // An edge-band sample's figure is its distance to the edge, within the band.
        if (samples[s][0] == "edge_band" && !samples[s][8].is_null())
            EXPECT_LE(samples[s][8].get<double>(), samples[s][9].get<double>()) << samples[s].dump();
    }
    EXPECT_EQ(pixel["state"], "ambiguous");
    EXPECT_TRUE(pixel["allowed"].is_null()) << "an ambiguous pixel is not judged";
    EXPECT_EQ(pixel["colour"], "agree");
    for (int k = 0; k < 3; ++k) {
        EXPECT_EQ(pixel["raster"][k].get<int>(), c.colour.png_image.at(x, y)[k]);
        EXPECT_EQ(pixel["raster"][k].get<int>(), c.raster.image.at(x, y)[k]);
        EXPECT_EQ(pixel["oracle"][k].get<int>(), c.oracle_image.at(x, y)[k]);
    }
    EXPECT_FALSE(pixel.contains("shadows")) << "the teapot's light casts no shadows";
    EXPECT_FALSE(pixel.contains("layers")) << "the teapot has no transparency";
}

TEST(PixelEvidence, pastTheCapThePixelsAreCountedNotListed) {
    const harness::Comparison all = compared("corpus/scenes/teapot.yaml", 4, 20000);
    const harness::Comparison capped = compared("corpus/scenes/teapot.yaml", 4, 3);
    const size_t notable = all.evidence["listed"].get<size_t>();
    ASSERT_GT(notable, 3u);
    EXPECT_EQ(capped.evidence["listed"], 3);
    EXPECT_EQ(capped.evidence["unlisted"], notable - 3);
    EXPECT_EQ(capped.evidence["pixels"].size(), 3u);
    // The ones listed are the first three row by row from the top (the JSON's keys are in text order).
    std::vector<std::pair<int, int>> rows;
    for (const auto& [key, pixel] : all.evidence["pixels"].items()) {
        const auto [x, y] = pixel_of(key);
        rows.push_back({y, x});
    }
    std::sort(rows.begin(), rows.end());
    for (size_t k = 0; k < 3; ++k)
        EXPECT_TRUE(capped.evidence["pixels"].contains(std::to_string(rows[k].second) + "," + std::to_string(rows[k].first)))
            << k;
    EXPECT_TRUE(compared("corpus/scenes/teapot.yaml", 1, 0).evidence.is_null()) << "none asked for, none built";
}

// With shadows and glass: the pixels the shadow model or the layers left open are listed with those verdicts, and
// the judged ones among them carry the interval their bytes lie in.
TEST(PixelEvidence, shadowAndLayerVerdictsAreListedWithTheJudgedPixelsInterval) {
    const harness::Comparison c = compared("corpus/scenes/shadows_and_glass.yaml", 1, 100000);
    ASSERT_FALSE(c.shadows.seen.empty());
    ASSERT_FALSE(c.transparency.open.empty());
    size_t open_shadow = 0, open_layers = 0, judged = 0;
    for (const auto& [key, pixel] : c.evidence["pixels"].items()) {
        const auto [x, y] = pixel_of(key);
        const size_t at = size_t(y) * size_t(c.width) + size_t(x);
        ASSERT_TRUE(pixel.contains("shadows")) << key;
        ASSERT_TRUE(pixel.contains("layers")) << key;
        const std::string shadows = pixel["shadows"].dump();
        const bool open = shadows.find("open_") != std::string::npos || shadows.find("inconsistent") != std::string::npos;
        EXPECT_EQ(open, (c.shadows.seen[at] & 0b11100) != 0) << key << " " << shadows;
        open_shadow += open;
        open_layers += !pixel["layers"].is_null() && pixel["state"] == "ambiguous";
        if (pixel["state"] == "judged") {
            ++judged;
            ASSERT_EQ(pixel["allowed"].size(), 3u) << key;
            for (int k = 0; k < 3; ++k) {
                const int byte = pixel["raster"][k].get<int>();
                const bool inside = pixel["allowed"][k][0].get<int>() <= byte && byte <= pixel["allowed"][k][1].get<int>();
                EXPECT_EQ(inside || pixel["colour"] != "agree", true) << key << " " << pixel.dump();
            }
        }
    }
    EXPECT_GT(open_shadow + open_layers, 0u) << "the scene has shadow edges or layer edges the oracle leaves open";
    // The layers leave a pixel open only where no sample is genuine: those are the ones the comparison counts.
    EXPECT_EQ(open_layers, c.transparency.edge_pixels + c.transparency.depth_pixels + c.transparency.order_pixels);
    EXPECT_GT(judged, 0u) << "some pixel is listed for its shadow verdicts alone, and judged";
}

}  // namespace
}  // namespace raster
