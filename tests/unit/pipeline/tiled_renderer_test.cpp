// The tiled fast path gives the reference path's bytes: the same image and visibility buffer on every corpus
// scene, sample count, pattern, MSAA, alpha, thread count and precision mode; and the same bytes on every SIMD
// target the CPU runs.
#include "raster/pipeline/tiled_renderer.h"

#include <filesystem>

#include <gtest/gtest.h>

#include "raster/formats/scene_loader.h"
#include "raster/pipeline/render.h"
#include "raster/pipeline/simd_targets.h"
#include "tests/support/pinned_simd_target.h"

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
            render_tiled_into(scene, options, PipelineStages{}, tiled);
            ASSERT_EQ(tiled.image.pixels, reference.image.pixels) << entry.path() << " samples " << v.samples;
            ASSERT_EQ(tiled.visibility.triangle, reference.visibility.triangle) << entry.path();
            ASSERT_EQ(tiled.visibility.view_depth, reference.visibility.view_depth) << entry.path();
            EXPECT_EQ(tiled.stats.covered_samples, reference.stats.covered_samples) << entry.path();
            // The scalar coverage kernel gives the SIMD one's bytes.
            RenderOptions portable = options;
            portable.allow_simd = false;
            RenderResult scalar;
            render_tiled_into(scene, portable, PipelineStages{}, scalar);
            ASSERT_EQ(scalar.image.pixels, reference.image.pixels) << entry.path() << " (portable)";
            ASSERT_EQ(scalar.visibility.view_depth, reference.visibility.view_depth) << entry.path() << " (portable)";
            // Without the visibility buffer the image is still the same.
            options.keep_visibility = false;
            RenderResult lean;
            render_tiled_into(scene, options, PipelineStages{}, lean);
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
                render_tiled_into(scene, options, PipelineStages{}, expected);
            }
            for (const int64_t target : targets) {
                const test_support::PinnedSimdTarget pinned(target);
                RenderResult result;
                render_tiled_into(scene, options, PipelineStages{}, result);
                ASSERT_EQ(result.image.pixels, expected.image.pixels)
                    << name << (msaa ? " msaa" : "") << " on " << simd_target_name(target);
                ++compared;
            }
        }
    }
    EXPECT_GE(compared, 6);
}

}  // namespace
}  // namespace raster
