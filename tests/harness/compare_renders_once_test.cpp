// A comparison judges the files the render job wrote, from the one frame whose samples it classes: a renderer
// behind the seam whose image is off is caught in both files; a seed 000 shading-depth config has its depth image
// judged and no colour image; raster itself agrees everywhere.
#include "harness/comparison/scene_comparison.h"

#include <utility>

#include <gtest/gtest.h>

#include "harness/comparison/comparison_output.h"
#include "raster/compat/scene_loader.h"

namespace raster {
namespace {

const std::filesystem::path kSource = RASTER_SOURCE_DIR;

// raster's frame with two of its image's rows swapped: what a writer or a read-back that loses the row order gives.
class RowsSwapped final : public Renderer {
public:
    std::string name() const override { return "raster, rows 100 and 200 swapped"; }
    bool gives_visibility() const override { return true; }
    void render_into(const Scene& scene, const RenderOptions& options, RenderResult& result) const override {
        RasterRenderer{}.render_into(scene, options, result);
        Image& image = result.image;
        for (int x = 0; x < image.width; ++x)
            for (int c = 0; c < image.channels; ++c) std::swap(image.at(x, 100)[c], image.at(x, 200)[c]);
    }
};

TEST(CompareScene, judgesTheFilesTheJobWroteFromTheFrameItClasses) {
    const Scene scene = load_scene(kSource / "corpus/scenes/single_triangle.yaml");
    const harness::Comparison clean = harness::compare_scene(scene, harness::ComparisonOptions{});
    EXPECT_EQ(clean.genuine_total(), 0u) << harness::comparison_summary(clean);
    EXPECT_TRUE(clean.colour.written);
    EXPECT_TRUE(clean.depth.written);
    EXPECT_EQ(clean.depth.png.pixels, uint64_t(clean.width) * clean.height);
    EXPECT_GT(clean.colour.png.judged, uint64_t(clean.width) * clean.height * 9 / 10);

    const RowsSwapped swapped;
    harness::ComparisonOptions options;
    options.renderer = &swapped;
    const harness::Comparison caught = harness::compare_scene(scene, options);
    EXPECT_EQ(caught.renderer, swapped.name());
    EXPECT_EQ(caught.visibility.counts.genuine_total(), 0u) << "the samples are raster's own";
    EXPECT_GT(caught.colour.png.genuine, 10u) << harness::comparison_summary(caught);
    EXPECT_EQ(caught.colour.png.genuine, caught.colour.ppm.genuine);
    EXPECT_EQ(caught.depth.genuine_pixels, 0u) << "the depth image comes from the samples, which are right";
}

TEST(CompareScene, judgesASeed000ShadingDepthConfigsDepthImageAndWritesNoColourImage) {
    const SceneFile file = load_scene_file(kSource / "corpus/seeds/000/test-shading-depth.yaml");
    ASSERT_TRUE(file.request.depth_image);
    harness::ComparisonOptions options;
    options.colour_output = false;
    const harness::Comparison comparison = harness::compare_scene(file.scene, options);
    EXPECT_FALSE(comparison.colour.written);
    EXPECT_EQ(comparison.colour.png.judged, 0u);
    EXPECT_TRUE(comparison.depth.written);
    EXPECT_EQ(comparison.depth.png.pixels, uint64_t(comparison.width) * comparison.height);
    EXPECT_EQ(comparison.genuine_total(), 0u) << harness::comparison_summary(comparison);
    EXPECT_EQ(harness::comparison_json(comparison)["outputs"]["color"], false);
}

}  // namespace
}  // namespace raster
