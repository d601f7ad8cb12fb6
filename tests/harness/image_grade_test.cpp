// raster grade's judgement: raster's own images pass, and images with planted defects fail, each as the class of
// failure it is (shifted by a pixel, holes along the edges, colours scaled, channels swapped, the wrong sample
// pattern, affine interpolation); the budget and the colour precision relax it as they say.
#include "harness/grading/image_grade.h"

#include <algorithm>
#include <utility>

#include <gtest/gtest.h>

#include "raster/compat/scene_loader.h"
#include "raster/frame/render.h"

namespace raster {
namespace {

const std::filesystem::path kScenes = std::filesystem::path(RASTER_SOURCE_DIR) / "corpus/scenes";

struct Rendered {
    Scene scene;
    RenderResult frame;
};

Rendered rendered(const char* name, int samples = 1) {
    Rendered r{load_scene(kScenes / name), {}};
    r.scene.settings.samples = samples;
    r.frame = render(r.scene, RenderOptions{});
    return r;
}

harness::ImageGrade graded(const Scene& scene, const Image& image, uint64_t budget = 0, int levels = 0) {
    harness::GradeOptions options;
    options.budget = budget;
    options.colour_levels = levels;
    return harness::grade_image(scene, image, options);
}

std::string counts_of(const harness::ImageGrade& g) { return harness::grade_json(g)["pixels"].dump(); }

TEST(ImageGrade, rastersOwnImagesPass) {
    for (const auto& [name, samples] : {std::pair{"teapot.yaml", 1}, {"teapot.yaml", 4}, {"shadows_and_glass.yaml", 1},
                                        {"textured_cube.yaml", 1}, {"interpenetrating.yaml", 16}}) {
        const Rendered r = rendered(name, samples);
        const harness::ImageGrade g = graded(r.scene, r.frame.image);
        EXPECT_TRUE(g.pass()) << name << " at " << samples << ": " << counts_of(g);
        EXPECT_EQ(g.failing(), 0u) << name;
        EXPECT_GT(g.count(harness::PixelGrade::pass), g.count(harness::PixelGrade::open) * 20) << name << ": "
                                                                                               << counts_of(g);
    }
}

TEST(ImageGrade, anImageShiftedByOnePixelFailsAlongEverySilhouette) {
    const Rendered r = rendered("teapot.yaml");
    Image shifted = r.frame.image;
    for (int y = 0; y < shifted.height; ++y)
        for (int x = shifted.width - 1; x > 0; --x) std::copy_n(r.frame.image.at(x - 1, y), 3, shifted.at(x, y));
    const harness::ImageGrade g = graded(r.scene, shifted);
    EXPECT_FALSE(g.pass());
    // The teapot moved right: background drawn where its left side is, teapot drawn where its right side is not.
    EXPECT_GT(g.count(harness::PixelGrade::missing), 100u) << counts_of(g);
    EXPECT_GT(g.count(harness::PixelGrade::unexpected), 100u) << counts_of(g);
}

TEST(ImageGrade, holesAlongTheEdgesAreMissingPixels) {
    const Rendered r = rendered("teapot.yaml");
    Image holed = r.frame.image;
    const VisibilityBuffer& v = r.frame.visibility;
    const uint8_t* background = r.frame.image.at(0, 0);
    size_t holes = 0;
    for (int y = 0; y < holed.height; ++y)
        for (int x = 0; x + 1 < holed.width; ++x)
            if (v.triangle[v.index(x, y, 0)] != kNoTriangle && v.triangle[v.index(x + 1, y, 0)] != kNoTriangle &&
                v.triangle[v.index(x, y, 0)] != v.triangle[v.index(x + 1, y, 0)] && (x + y) % 7 == 0) {
                std::copy_n(background, 3, holed.at(x, y));  // a crack between two of the teapot's triangles
                ++holes;
            }
    ASSERT_GT(holes, 200u);
    const harness::ImageGrade g = graded(r.scene, holed);
    EXPECT_FALSE(g.pass());
    // Most cracks are at decided pixels (their sample far from the shared edge, in units of the band).
    EXPECT_GT(g.count(harness::PixelGrade::missing), holes / 2) << counts_of(g);
    EXPECT_EQ(g.count(harness::PixelGrade::unexpected), 0u) << counts_of(g);
}

TEST(ImageGrade, scaledColoursAndSwappedChannelsAreWrongColours) {
    const Rendered r = rendered("teapot.yaml");
    Image scaled = r.frame.image, swapped = r.frame.image;
    for (size_t i = 0; i < scaled.pixels.size(); ++i) scaled.pixels[i] = uint8_t(scaled.pixels[i] * 0.9);
    for (size_t i = 0; i < swapped.pixels.size(); i += 3) std::swap(swapped.pixels[i], swapped.pixels[i + 2]);
    for (const Image* image : {&scaled, &swapped}) {
        const harness::ImageGrade g = graded(r.scene, *image);
        EXPECT_FALSE(g.pass());
        EXPECT_GT(g.count(harness::PixelGrade::wrong_colour), 100000u) << counts_of(g);
    }
}

TEST(ImageGrade, theWrongSamplePatternFailsAtTheEdges) {
    Rendered r = rendered("teapot.yaml", 4);
    Scene grid = r.scene;
    grid.settings.pattern = SamplePattern::grid;
    const Image on_grid = render(grid, RenderOptions{}).image;
    const harness::ImageGrade g = graded(r.scene, on_grid);  // promised: the standard pattern
    EXPECT_FALSE(g.pass());
    EXPECT_GT(g.failing(), 100u) << counts_of(g);
    EXPECT_TRUE(graded(grid, on_grid).pass()) << "graded with the pattern it was drawn with";
}

TEST(ImageGrade, affineInterpolationFailsOnAPerspectiveFloor) {
    const Rendered r = rendered("checker_floor.yaml");
    Scene affine = r.scene;
    affine.settings.modes.interpolation = Interpolation::affine;
    const harness::ImageGrade g = graded(r.scene, render(affine, RenderOptions{}).image);
    EXPECT_FALSE(g.pass());
    EXPECT_GT(g.count(harness::PixelGrade::wrong_colour), 1000u) << counts_of(g);
    EXPECT_TRUE(graded(r.scene, r.frame.image).pass());
}

TEST(ImageGrade, theBudgetAndTheColourPrecisionRelaxTheVerdictAsTheySay) {
    const Rendered r = rendered("teapot.yaml");
    Image nudged = r.frame.image;
    for (int x = 300; x < 310; ++x) nudged.at(x, 400)[0] = uint8_t(std::min(255, nudged.at(x, 400)[0] + 12));
    const harness::ImageGrade strict = graded(r.scene, nudged);
    ASSERT_GT(strict.failing(), 0u) << "twelve levels off, on the teapot's body";
    EXPECT_FALSE(strict.pass());
    EXPECT_TRUE(graded(r.scene, nudged, strict.failing()).pass());
    EXPECT_FALSE(graded(r.scene, nudged, strict.failing() - 1).pass());
    EXPECT_TRUE(graded(r.scene, nudged, 0, 12).pass()) << "twelve levels of colour precision";
    // The mask paints each failing pixel red (a wrong colour), the passing ones black.
    const Image mask = harness::grade_mask(strict);
    EXPECT_EQ(mask.at(0, 0)[0], 0);
    size_t red = 0;
    for (int x = 300; x < 310; ++x) red += mask.at(x, 400)[0] == 230;
    EXPECT_EQ(red, strict.failing());
}

TEST(ImageGrade, anImageOfAnotherSizeIsRefused) {
    const Rendered r = rendered("single_triangle.yaml");
    EXPECT_THROW(graded(r.scene, Image(3, 2, 3)), std::invalid_argument);
}

}  // namespace
}  // namespace raster
