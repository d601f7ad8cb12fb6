// The tiled fast path gives the reference path's bytes: the same image and visibility buffer on every corpus
// scene, sample count, pattern, MSAA, alpha, thread count and precision mode; the same bytes on every SIMD target
// the CPU runs; and draw order, transparency and setup lists across the front end's chunks and the table's parts.
#include "raster/frame/tiled_renderer.h"

#include <cmath>
#include <filesystem>

#include <gtest/gtest.h>

#include "raster/compat/scene_loader.h"
#include "raster/geometry/front_end.h"
#include "raster/frame/render.h"
#include "raster/rasterize/reference_rasterizer.h"
#include "raster/geometry/sample_pattern.h"
#include "raster/geometry/setup_table.h"
#include "raster/rasterize/tile_rasterizer.h"
#include "raster/simd/simd_targets.h"
#include "tests/support/pinned_simd_target.h"
#include "tests/support/quad_meshes.h"

namespace raster {
namespace {

const std::string kCorpus = std::string(RASTER_SOURCE_DIR) + "/corpus/scenes/";

struct Variant {
    int samples;
    SamplePattern pattern;
    bool msaa;
    bool alpha;
    int threads;
    PrecisionModes modes = {};
};

PrecisionModes modes(EdgeArithmetic edges, Interpolation interpolation, DepthFormat depth, Clipping clipping, bool hiz) {
    return PrecisionModes{edges, interpolation, depth, clipping, hiz};
}

TEST(TiledRender, matchesTheReferencePathByteForByte) {
    const Variant variants[] = {
        {1, SamplePattern::standard, false, false, 2},
        {4, SamplePattern::standard, true, true, 1},
        {16, SamplePattern::standard, false, false, 3},
        {9, SamplePattern::grid, true, false, 2},
        {1, SamplePattern::standard, false, false, 2,
         modes(EdgeArithmetic::float32, Interpolation::affine, DepthFormat::fixed24, Clipping::guard_band, false)},
        {4, SamplePattern::standard, true, false, 2,
         modes(EdgeArithmetic::fixed, Interpolation::perspective, DepthFormat::float_z, Clipping::guard_band, true)},
    };
    int compared = 0;
    for (const auto& entry : std::filesystem::directory_iterator(kCorpus)) {
        Scene scene = load_scene(entry.path());
        // Keep the big scenes quick: a quarter of the size keeps every tile-boundary case (sizes not multiples of
        // the tile).
        if (scene.settings.width > 400) {
            scene.settings.width /= 3;
            scene.settings.height /= 3;
        }
        for (const Variant& v : variants) {
            scene.settings.samples = v.samples;
            scene.settings.pattern = v.pattern;
            scene.settings.msaa = v.msaa;
            scene.settings.modes = v.modes;
            RenderOptions options;
            options.alpha = v.alpha;
            options.threads = v.threads;
            RenderOptions reference_options = options;
            reference_options.path = RasterPath::reference;
            const RenderResult reference = render(scene, reference_options);
            RenderResult tiled;
            render_into(scene, options, tiled);
            ASSERT_EQ(tiled.image.pixels, reference.image.pixels) << entry.path() << " samples " << v.samples;
            ASSERT_EQ(tiled.visibility.triangle, reference.visibility.triangle) << entry.path();
            ASSERT_EQ(tiled.visibility.view_depth, reference.visibility.view_depth) << entry.path();
            EXPECT_EQ(tiled.stats.covered_samples, reference.stats.covered_samples) << entry.path();
            // The scalar coverage kernel gives the SIMD one's bytes.
            RenderOptions portable = options;
            portable.allow_simd = false;
            RenderResult scalar;
            render_into(scene, portable, scalar);
            ASSERT_EQ(scalar.image.pixels, reference.image.pixels) << entry.path() << " (portable)";
            ASSERT_EQ(scalar.visibility.view_depth, reference.visibility.view_depth) << entry.path() << " (portable)";
            // Without the visibility buffer the image is still the same.
            options.keep_visibility = false;
            RenderResult lean;
            render_into(scene, options, lean);
            ASSERT_EQ(lean.image.pixels, reference.image.pixels) << entry.path() << " (no visibility buffer)";
            // (A scene with transparency keeps it: the transparency pass reads the opaque samples.)
            EXPECT_EQ(lean.visibility.size(), has_transparency(scene) ? reference.visibility.size() : 0u);
            ++compared;
        }
    }
    EXPECT_GE(compared, 6 * 6);
}

TEST(TiledRender, everySimdTargetTheCpuRunsGivesTheScalarFallbacksBytes) {
    // The production path end to end (lighting and coverage kernels), pinned to each target in turn: Blinn-Phong
    // and Phong with textures, shadows and glass, at 1 sample and 4x MSAA.
    const std::vector<int64_t> targets = simd_targets();
    ASSERT_GE(targets.size(), 1u);
    int compared = 0;
    for (const char* name : {"teapot.yaml", "shadows_and_glass.yaml", "textured_cube.yaml"}) {
        for (const bool msaa : {false, true}) {
            Scene scene = load_scene(kCorpus + name);
            scene.settings.samples = msaa ? 4 : 1;
            scene.settings.msaa = msaa;
            if (std::string(name) == "teapot.yaml") scene.settings.shading = ShadingMode::phong;
            RenderOptions options;
            options.threads = 2;
            RenderResult expected;
            {
                const test_support::PinnedSimdTarget fallback_only(targets.back());
                render_into(scene, options, expected);
            }
            for (const int64_t target : targets) {
                const test_support::PinnedSimdTarget pinned(target);
                RenderResult result;
                render_into(scene, options, result);
                ASSERT_EQ(result.image.pixels, expected.image.pixels)
                    << name << (msaa ? " msaa" : "") << " on " << simd_target_name(target);
                ++compared;
            }
        }
    }
    EXPECT_GE(compared, 6);
}

// Two coincident grids of 66,248 triangles each, 33 chunks, binned in 16 groups: every depth test between them is
// a tie, which keeps the earlier triangle, so the first grid's colour must cover the image on both renderers.
TEST(TiledRender, aSceneOfManyChunksKeepsTheDrawOrderAcrossThem) {
    const glm::vec3 first(0.81f, 0.13f, 0.27f), second(0.12f, 0.83f, 0.31f);
    constexpr int kQuadsPerSide = 182;
    constexpr uint32_t kFirstGridTriangles = 2 * kQuadsPerSide * kQuadsPerSide;
    for (RasterPath path : {RasterPath::tiled, RasterPath::reference}) {
        const Scene scene = test_support::unlit_scene(
            {test_support::grid_mesh(kQuadsPerSide, first), test_support::grid_mesh(kQuadsPerSide, second)});
        RenderOptions options;
        options.path = path;
        options.threads = 2;
        const RenderResult result = render(scene, options);
        EXPECT_EQ(result.stats.rasterized, 2 * kFirstGridTriangles);
        const uint8_t* centre = result.image.at(48, 48);
        for (int c = 0; c < 3; ++c)
            EXPECT_EQ(centre[c], static_cast<int>(std::floor(first[c] * 255.0 + 0.5))) << "channel " << c;
        size_t covered = 0;
        for (uint32_t id : result.visibility.triangle) {
            if (id == kNoTriangle) continue;
            ++covered;
            ASSERT_LT(id, kFirstGridTriangles) << "the second grid won a tie";
        }
        EXPECT_GT(covered, 1000u);
    }
}

// A transparent grid between two opaque ones, over several chunks: the same bytes as the reference renderer.
TEST(TiledRender, aTransparentMeshAmongChunksGivesTheReferenceBytes) {
    Scene scene = test_support::unlit_scene({test_support::grid_mesh(40, glm::vec3(0.2f, 0.5f, 0.7f)),
                                             test_support::grid_mesh(30, glm::vec3(0.9f, 0.4f, 0.1f), 0.5f),
                                             test_support::grid_mesh(40, glm::vec3(0.6f, 0.6f, 0.2f))});
    scene.meshes[1].transform.steps = {TranslateStep{{0.2f, 0.1f, 0.5f}}};  // in front, shifted
    scene.meshes[2].transform.steps = {TranslateStep{{-0.3f, 0.2f, -0.5f}}};
    RenderOptions options;
    options.threads = 2;
    RenderOptions reference_options = options;
    reference_options.path = RasterPath::reference;
    const RenderResult tiled = render(scene, options), reference = render(scene, reference_options);
    EXPECT_GT(tiled.stats.transparent_fragments, 0u);
    EXPECT_EQ(tiled.stats.transparent_fragments, reference.stats.transparent_fragments);
    EXPECT_EQ(tiled.image.pixels, reference.image.pixels);
}

// rasterize_tiled on one list of more setups than a part holds (2^16): the reference rasterizer's visibility.
TEST(TiledRender, aListLongerThanAPartGivesTheReferenceRasterizersSamples) {
    const Scene scene = test_support::unlit_scene({test_support::grid_mesh(190, glm::vec3(0.5f))});
    const TransformedScene geometry = run_vertex_stage(scene, vertex_stage_needs(scene.settings.shading));
    const FrameParams frame = frame_params_for(scene, sample_offsets(4, SamplePattern::standard), 2);
    const std::vector<TriangleSetup> setups = set_up_triangles(geometry, frame, false);
    ASSERT_GT(setups.size(), size_t{kSetupsPerPart});
    VisibilityBuffer tiled, reference;
    rasterize_tiled(setups, frame, true, tiled);
    rasterize_reference(setups, frame, reference);
    EXPECT_EQ(tiled.triangle, reference.triangle);
    EXPECT_EQ(tiled.view_depth, reference.view_depth);
    size_t late = 0;  // samples won by a setup past the first part
    for (uint32_t id : tiled.triangle) late += id != kNoTriangle && id >= kSetupsPerPart;
    EXPECT_GT(late, 100u);
}

}  // namespace
}  // namespace raster
