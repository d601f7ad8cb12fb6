// Transparency: a pane's blend over the background and over an opaque surface by the compositing formula, layers in
// depth order whatever the draw order, the weighted average's own formula, MSAA's shading rate in both modes, a fully transparent pane changing no
// byte, an opaque surface in front hiding the panes, RGBA alpha, the A-buffer's cap, panes casting no shadow, and the
// split of the front end's chunks.
#include "raster/resolve/transparency.h"

#include <cmath>
#include <utility>

#include <gtest/gtest.h>

#include "raster/core/errors.h"
#include "raster/geometry/front_end.h"
#include "raster/frame/render.h"
#include "raster/frame/shadow_pass.h"
#include "raster/geometry/vertex_stage.h"
#include "tests/support/quad_meshes.h"

namespace raster {
namespace {

SceneMesh pane(float depth, float half, const glm::vec3& colour, float opacity) {
    return test_support::facing_pane(depth, half, colour, opacity);
}

// Unlit panes on a background, 32 x 32 pixels, the camera at (0, 0, 5) looking at the origin.
Scene pane_scene(std::vector<SceneMesh> panes, int samples = 1) {
    Scene scene;
    scene.settings.width = scene.settings.height = 32;
    scene.settings.samples = samples;
    scene.settings.shading = ShadingMode::unlit;
    scene.settings.background = glm::vec3(0.2f, 0.4f, 0.6f);
    scene.meshes = std::move(panes);
    return scene;
}

// The bytes of a linear value, as docs/conventions.md writes them.
int byte_of(double v) { return static_cast<int>(std::floor(std::clamp(v, 0.0, 1.0) * 255.0 + 0.5)); }

RenderResult draw(const Scene& scene, RasterPath path = RasterPath::tiled) {
    RenderOptions options;
    options.path = path;
    options.threads = 2;
    return render(scene, options);
}

// Colours whose blends here lie well away from a byte's rounding boundary (x.5 / 255).
const glm::vec3 kRed(0.81f, 0.13f, 0.27f), kGreen(0.12f, 0.83f, 0.31f), kGrey(0.52f, 0.52f, 0.52f);

TEST(Transparency, aPaneOverTheBackgroundIsItsOpacityTimesItsColourPlusTheRestOfTheBackground) {
    for (RasterPath path : {RasterPath::tiled, RasterPath::reference}) {
        const Scene scene = pane_scene({pane(3.0f, 1.0f, kRed, 0.4f)});
        const RenderResult result = draw(scene, path);
        EXPECT_GT(result.stats.transparent_fragments, 0u);
        const uint8_t* centre = result.image.at(16, 16);
        for (int c = 0; c < 3; ++c)
            EXPECT_EQ(centre[c], byte_of(0.4 * kRed[c] + 0.6 * scene.settings.background[c])) << c;
        const uint8_t* corner = result.image.at(0, 0);  // the pane does not reach it
        for (int c = 0; c < 3; ++c) EXPECT_EQ(corner[c], byte_of(scene.settings.background[c])) << c;
    }
}

TEST(Transparency, layersBlendNearestFirstWhateverTheDrawOrder) {
    // Green at depth 2 (opacity 0.5) in front of red at depth 3 (0.4) in front of an opaque grey wall at depth 4.
    const double expected_red = 0.5 * kGreen[0] + 0.5 * (0.4 * kRed[0] + 0.6 * kGrey[0]);
    const Scene ordered = pane_scene({pane(4.0f, 3.0f, kGrey, 1.0f), pane(2.0f, 1.0f, kGreen, 0.5f),
                                      pane(3.0f, 1.0f, kRed, 0.4f)});
    const Scene reversed = pane_scene({pane(3.0f, 1.0f, kRed, 0.4f), pane(2.0f, 1.0f, kGreen, 0.5f),
                                       pane(4.0f, 3.0f, kGrey, 1.0f)});
    const RenderResult a = draw(ordered), b = draw(reversed);
    EXPECT_EQ(a.image.at(16, 16)[0], byte_of(expected_red));
    EXPECT_EQ(a.image.pixels, b.image.pixels);
}

TEST(Transparency, theWeightedModeAveragesTheLayersByOpacityInAnyOrder) {
    Scene scene = pane_scene({pane(2.0f, 1.0f, kGreen, 0.5f), pane(3.0f, 1.0f, kRed, 0.4f)});
    scene.settings.transparency.mode = TransparencyMode::weighted;
    const double transmittance = 0.5 * 0.6;
    for (int c = 0; c < 3; ++c) {
        const double average = (0.5 * kGreen[c] + 0.4 * kRed[c]) / 0.9;
        EXPECT_EQ(draw(scene).image.at(16, 16)[c],
                  byte_of(average * (1.0 - transmittance) + transmittance * scene.settings.background[c]))
            << c;
    }
    Scene swapped = scene;
    std::swap(swapped.meshes[0], swapped.meshes[1]);
    EXPECT_EQ(draw(scene).image.pixels, draw(swapped).image.pixels);
}

// MSAA shades a transparent triangle once per pixel in either mode: on one layer, where both modes are exact, the
// weighted mode gives the sorted mode's bytes. The pane's colour runs from red to blue across it, so shading each
// sample instead (as SSAA does, which the test shows differs here) would move the bytes.
TEST(Transparency, msaaShadesATransparentTriangleOncePerPixelInEitherMode) {
    Scene scene = pane_scene({pane(3.0f, 1.0f, glm::vec3(1.0f), 0.5f)}, 4);
    mutable_data(scene.meshes[0]).colors = {{1, 0, 0}, {0, 0, 1}, {0, 0, 1}, {1, 0, 0}};  // left red, right blue
    scene.settings.msaa = true;
    const RenderResult sorted = draw(scene);
    scene.settings.transparency.mode = TransparencyMode::weighted;
    EXPECT_EQ(draw(scene).image.pixels, sorted.image.pixels);
    scene.settings.msaa = false;
    EXPECT_NE(draw(scene).image.pixels, sorted.image.pixels) << "the shading rate changes no byte of this scene";
}

TEST(Transparency, aFullyTransparentPaneChangesNoByte) {
    for (int samples : {1, 4}) {
        const Scene without = pane_scene({pane(4.0f, 1.5f, kGrey, 1.0f)}, samples);
        Scene with = without;
        with.meshes.push_back(pane(2.0f, 1.0f, kRed, 0.0f));
        EXPECT_EQ(draw(with).image.pixels, draw(without).image.pixels) << samples;
    }
}

TEST(Transparency, anOpaqueSurfaceInFrontHidesEveryPaneBehindIt) {
    const Scene front_only = pane_scene({pane(1.0f, 3.0f, kGrey, 1.0f)});
    Scene with_panes = pane_scene({pane(2.0f, 1.0f, kGreen, 0.5f), pane(1.0f, 3.0f, kGrey, 1.0f),
                                   pane(3.0f, 1.0f, kRed, 0.4f)});
    const RenderResult result = draw(with_panes);
    EXPECT_EQ(result.stats.transparent_fragments, 0u);
    EXPECT_EQ(result.image.pixels, draw(front_only).image.pixels);
}

TEST(Transparency, rgbaOutputGivesThePanesAlphaAndItsOwnColour) {
    RenderOptions options;
    options.alpha = true;
    const RenderResult result = render(pane_scene({pane(3.0f, 1.0f, kRed, 0.4f)}), options);
    const uint8_t* centre = result.image.at(16, 16);
    for (int c = 0; c < 3; ++c) EXPECT_EQ(centre[c], byte_of(kRed[c])) << c;
    EXPECT_EQ(centre[3], byte_of(0.4));
}

TEST(Transparency, theSortedModeRefusesMoreFragmentsThanItsCap) {
    Scene scene = pane_scene({pane(2.0f, 1.0f, kGreen, 0.5f), pane(3.0f, 1.0f, kRed, 0.4f)});
    scene.settings.transparency.max_fragments = 100;
    EXPECT_THROW(draw(scene), InputError);
    scene.settings.transparency.mode = TransparencyMode::weighted;  // keeps no fragment lists
    EXPECT_NO_THROW(draw(scene));
}

TEST(Transparency, anOpaqueSceneSetsNothingAside) {
    const Scene scene = pane_scene({pane(2.0f, 1.0f, kGreen, 1.0f)});
    EXPECT_TRUE(transparent_triangles(scene).empty());
    const RenderResult result = draw(scene);
    EXPECT_TRUE(result.workspace.front_end.transparent_setups.empty());
    EXPECT_EQ(result.stats.ms_transparency, 0.0);
}

TEST(Transparency, panesCastNoShadow) {
    // A light straight above a floor, a translucent pane between them: the floor below the pane is lit.
    Scene scene;
    scene.settings.shading = ShadingMode::blinn_phong;
    scene.lights.push_back({glm::vec3(0, 4, 0), glm::vec3(1.0f), 1.0f, false, true});
    SceneMesh floor = pane(0.0f, 5.0f, kGrey, 1.0f), glass = pane(0.0f, 1.0f, kRed, 0.5f);
    for (auto& p : mutable_data(floor).positions) p = glm::vec3(p.x, 0.0f, p.y);
    for (auto& p : mutable_data(glass).positions) p = glm::vec3(p.x, 2.0f, p.y);
    scene.meshes = {floor, glass};
    const TransformedScene geometry = run_vertex_stage(scene, vertex_stage_needs(scene.settings.shading));
    const ShadowMaps maps = render_shadow_maps(scene, geometry.world_position, raster_backend(RasterPath::tiled), 2);
    EXPECT_EQ(maps.visibility(0, {0.1f, 0.0f, 0.2f}, {0, 1, 0}), 1.0f);
    scene.meshes[1].material.opacity = 1.0f;  // the same pane opaque does
    const ShadowMaps opaque = render_shadow_maps(scene, geometry.world_position, raster_backend(RasterPath::tiled), 2);
    EXPECT_EQ(opaque.visibility(0, {0.1f, 0.0f, 0.2f}, {0, 1, 0}), 0.0f);
}

TEST(Transparency, theChunkSplitKeepsEachChunksOpaqueSetupsAndEveryTransparentOneInDrawOrder) {
    // Triangles 0..11 over three chunks; every third one is transparent.
    std::vector<uint8_t> transparent(12, 0);
    for (size_t id = 0; id < transparent.size(); id += 3) transparent[id] = 1;
    std::vector<std::vector<TriangleSetup>> chunks(3);
    for (uint32_t id = 0; id < 12; ++id) chunks[id / 4].emplace_back().triangle_id = id;
    std::vector<TriangleSetup> out(5);  // stale contents, replaced
    split_transparent_setups(transparent, chunks, out);
    auto ids = [](const std::vector<TriangleSetup>& setups) {
        std::vector<uint32_t> result;
        for (const TriangleSetup& t : setups) result.push_back(t.triangle_id);
        return result;
    };
    EXPECT_EQ(ids(out), (std::vector<uint32_t>{0, 3, 6, 9}));
    EXPECT_EQ(ids(chunks[0]), (std::vector<uint32_t>{1, 2}));
    EXPECT_EQ(ids(chunks[1]), (std::vector<uint32_t>{4, 5, 7}));
    EXPECT_EQ(ids(chunks[2]), (std::vector<uint32_t>{8, 10, 11}));
}

}  // namespace
}  // namespace raster
