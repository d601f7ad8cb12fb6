// The oracle's transparency model on its own: the layer caster's filter collecting every hit along a ray nearest
// first, the layered resolve giving the compositing formula exactly (within its stated float allowance) and
// holding raster's bytes, the view-depth tie at its bound, and a pane edge Embree misses found by the grid.
#include <cmath>
#include <utility>

#include <glm/trigonometric.hpp>
#include <gtest/gtest.h>

#include "oracle/compare/layer_check.h"
#include "oracle/compare/sample_classifier.h"
#include "oracle/reference/layer_caster.h"
#include "oracle/reference/layer_resolve.h"
#include "oracle/reference/precision.h"
#include "oracle/reference/ray_caster.h"
#include "oracle/reference/reference_geometry.h"
#include "oracle/reference/sample_positions.h"
#include "oracle/reference/scene_geometry.h"
#include "oracle/reference/shading_precision.h"
#include "raster/frame/render.h"
#include "tests/support/quad_meshes.h"

namespace raster::oracle {
namespace {

using test_support::facing_pane;

Scene three_panes() {
    Scene scene;
    scene.settings.width = scene.settings.height = 24;
    scene.settings.shading = ShadingMode::unlit;
    scene.settings.background = glm::vec3(0.2f, 0.45f, 0.7f);
    // Drawn far to near; an opaque wall behind them all.
    scene.meshes = {facing_pane(4.0, 3.0, {0.52f, 0.52f, 0.52f}, 1.0f), facing_pane(3.0, 0.5, {0.81f, 0.13f, 0.27f}, 0.4f),
                    facing_pane(2.5, 0.5, {0.12f, 0.83f, 0.31f}, 0.5f), facing_pane(2.0, 0.5, {0.3f, 0.3f, 0.9f}, 0.25f)};
    return scene;
}

TEST(LayerCaster, collectsEveryTransparentHitAlongTheRayNearestFirst) {
    const Scene scene = three_panes();
    const OracleScene geometry = oracle_scene(scene);
    const SampleLayers layers = trace_layers(scene, geometry, OracleOptions{});
    SampleBuffer opaque;
    render_oracle(scene, geometry, OracleOptions{}, opaque);
    const size_t centre = opaque.index(12, 12, 0);
    ASSERT_EQ(layers.count(centre), 3u);
    EXPECT_NEAR(layers.of(centre)[0].view_depth, 2.0, 1e-5);
    EXPECT_NEAR(layers.of(centre)[1].view_depth, 2.5, 1e-5);
    EXPECT_NEAR(layers.of(centre)[2].view_depth, 3.0, 1e-5);
    EXPECT_GE(opaque.triangle[centre], 0u);
    EXPECT_LT(opaque.triangle[centre], 2u);  // the wall, not a pane: transparent surfaces are not visibility
    EXPECT_EQ(layers.count(opaque.index(0, 0, 0)), 0u);  // outside the panes
    const Scene opaque_only = [] {
        Scene s = three_panes();
        s.meshes.resize(1);
        return s;
    }();
    EXPECT_TRUE(trace_layers(opaque_only, oracle_scene(opaque_only), OracleOptions{}).first.empty());
}

TEST(LayeredResolve, isTheCompositingFormulaAndHoldsRastersBytes) {
    const Scene scene = three_panes();
    const OracleScene geometry = oracle_scene(scene);
    const OracleShader shader(scene, geometry);
    LayeredSample sample;
    sample.opaque = {0, Interval3(glm::dvec3(1.0 / 3.0))};
    for (uint32_t id : {6u, 4u, 2u}) sample.layers.push_back({id, Interval3(glm::dvec3(1.0 / 3.0))});  // near first
    const ResolveSettings settings{1, false, false, glm::dvec3(scene.settings.background)};
    for (TransparencyMode mode : {TransparencyMode::sorted, TransparencyMode::weighted}) {
        const PixelColour colour = resolve_layered_pixel(shader, settings, mode, &sample);
        // The formula in double, from the scene's values.
        const double a[3] = {0.25, 0.5, 0.4};
        const glm::dvec3 c[3] = {glm::dvec3(glm::vec3(0.3f, 0.3f, 0.9f)), glm::dvec3(glm::vec3(0.12f, 0.83f, 0.31f)),
                                 glm::dvec3(glm::vec3(0.81f, 0.13f, 0.27f))};
        glm::dvec3 sum(0.0), average(0.0);
        double t = 1.0, alpha = 0.0;
        for (int i = 0; i < 3; ++i) {
            sum += t * a[i] * c[i];
            average += a[i] * c[i];
            alpha += a[i];
            t *= 1.0 - a[i];
        }
        const glm::dvec3 layers = mode == TransparencyMode::sorted ? sum : average / alpha * (1.0 - t);
        const glm::dvec3 expected = layers + t * glm::dvec3(glm::vec3(0.52f));
        for (int k = 0; k < 3; ++k) {
            EXPECT_LE(colour.channel[k].lo, expected[k]) << k;
            EXPECT_GE(colour.channel[k].hi, expected[k]) << k;
            // No wider than the stated float allowance (and the pixel average's rounding).
            EXPECT_LT(colour.channel[k].hi - colour.channel[k].lo,
                      2.0 * float_gamma(kLayerRoundings * 3 + kCompositeRoundings + 8))
                << k;
        }
        // raster's bytes at the centre pixel are inside the bytes the interval allows.
        Scene rendered = scene;
        rendered.settings.transparency.mode = mode;
        const RenderResult result = render(rendered, RenderOptions{});
        for (int k = 0; k < 3; ++k) {
            const ByteRange allowed = byte_range(colour.channel[k]);
            EXPECT_TRUE(allowed.contains(result.image.at(12, 12)[k])) << k << " " << int(result.image.at(12, 12)[k]);
        }
    }
}

TEST(LayerCheck, viewDepthsTieWithinTheirAgreementTolerancesAndNotBeyond) {
    const Scene scene = three_panes();
    const OracleScene geometry = oracle_scene(scene);
    const ReferenceGeometry reference(scene, geometry);
    const glm::dvec2 screen(12.5, 12.5);
    const double reach = agreement_tolerance(reference, 2, screen).view_depth + agreement_tolerance(reference, 4, screen).view_depth;
    ASSERT_TRUE(std::isfinite(reach));
    EXPECT_TRUE(view_depth_tie(reference, 2, 3.0, 4, 3.0 + 0.999 * reach, screen));
    EXPECT_FALSE(view_depth_tie(reference, 2, 3.0, 4, 3.0 + 1.001 * reach, screen));
}

TEST(LayerCheck, aPaneEdgeWithinTheSnapRadiusOfASampleIsOpenEvenWhereEmbreeMissesIt) {
    // A pane whose right edge lies a hair right of the centre sample of pixel 12's column: Embree's ray, a hair to
    // its left or right, may or may not hit it, and raster's snapped edge may fall either side.
    for (double side : {1.0, -1.0}) {  // the edge a hair right of the sample (Embree hits), then left (it misses)
        Scene scene = three_panes();
        scene.meshes.resize(1);
        const double depth = 3.0, tan_half = std::tan(glm::radians(double(scene.camera.fov_y_degrees)) / 2.0);
        const double pixel = 2.0 * depth * tan_half / scene.settings.height;  // world size of a pixel at that depth
        SceneMesh edge = facing_pane(depth, 1.0, {0.81f, 0.13f, 0.27f}, 0.4f);
        const float right = static_cast<float>(0.5 * pixel + side * pixel / 4096.0);  // pixel 12's sample: 0.5 px
        for (auto& p : mutable_data(edge).positions) p.x = p.x > 0.0f ? right : -1.0f;
        scene.meshes.push_back(edge);
        const OracleScene geometry = oracle_scene(scene);
        const ReferenceGeometry reference(scene, geometry);
        SampleBuffer opaque;
        render_oracle(scene, geometry, OracleOptions{}, opaque);
        const SampleLayers layers = trace_layers(scene, geometry, OracleOptions{});
        EXPECT_EQ(layers.count(opaque.index(12, 12, 0)), side > 0 ? 1u : 0u) << side;
        LayerCheckInputs inputs;
        inputs.scene = &scene;
        inputs.layers = &layers;
        inputs.oracle = &opaque;
        inputs.reference = &reference;
        inputs.transparent = traced_triangles(scene, geometry, Surfaces::transparent);
        inputs.offsets = sample_offsets_on_grid(1, SamplePattern::standard, scene.settings.snap_bits);
        const LayerVerdicts verdicts = check_layers(inputs);
        EXPECT_EQ(verdicts.open[opaque.index(12, 12, 0)], LayerOpen::edge) << side;
        EXPECT_EQ(verdicts.open[opaque.index(10, 12, 0)], LayerOpen::none) << side;  // well inside the pane
        EXPECT_EQ(verdicts.open[opaque.index(14, 12, 0)], LayerOpen::none) << side;  // well outside
    }
}

}  // namespace
}  // namespace raster::oracle
