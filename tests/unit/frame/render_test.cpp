// End to end: every corpus scene renders, and each shows what it was built to show.
#include "raster/frame/render.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "raster/compat/scene_loader.h"
#include "raster/transform/transform.h"
#include "raster/geometry/vertex_stage.h"
#include "tests/support/reference_upscale.h"

namespace raster {
namespace {

const std::string kCorpus = std::string(RASTER_SOURCE_DIR) + "/corpus/scenes/";

RenderResult render_corpus(const std::string& name, int threads = 0) {
    Scene scene = load_scene(kCorpus + name);
    RenderOptions options;
    options.threads = threads;
    return render(scene, options);
}

const uint8_t* pixel(const Image& image, int x, int y) { return image.at(x, y); }

TEST(Render, everyCorpusSceneRendersSomething) {
    for (const auto& entry : std::filesystem::directory_iterator(kCorpus)) {
        const Scene scene = load_scene(entry.path());
        const RenderResult result = render(scene, RenderOptions{});
        EXPECT_GT(result.stats.covered_samples, result.stats.samples / 50) << entry.path();
        EXPECT_LT(result.stats.covered_samples, result.stats.samples) << entry.path();
    }
}

TEST(Render, sameBytesForAnyThreadCount) {
    for (const char* name : {"teapot.yaml", "perspective_quad.yaml"}) {
        const RenderResult one = render_corpus(name, 1), two = render_corpus(name, 2), five = render_corpus(name, 5);
        EXPECT_EQ(one.image.pixels, two.image.pixels) << name;
        EXPECT_EQ(one.image.pixels, five.image.pixels) << name;
    }
}

// A reduced-resolution frame is the scene's frame at the internal size, every stage included (shadows, textures,
// transparency, clipping), with its image stretched by the upscale's convention: the native frame there is what the
// oracle judges everywhere else, and the stretch is written out independently (tests/support/reference_upscale.h).
TEST(Render, aReducedResolutionFrameIsTheNativeFrameAtTheInternalSizeUpscaled) {
    for (const char* name : {"teapot.yaml", "shadows_and_glass.yaml", "textured_cube.yaml", "near_crossing.yaml"})
        for (int divisor : {2, 4}) {
            Scene scene = load_scene(kCorpus + name);
            Scene internal = scene;
            internal.settings.width /= divisor;
            internal.settings.height /= divisor;
            scene.settings.resolution_divisor = divisor;
            ASSERT_EQ(scene.settings.width % divisor, 0) << name;
            const RenderResult reduced = render(scene, RenderOptions{}), native = render(internal, RenderOptions{});
            const std::string what = std::string(name) + " at divisor " + std::to_string(divisor);
            EXPECT_EQ(reduced.image.width, scene.settings.width) << what;
            EXPECT_EQ(reduced.image.height, scene.settings.height) << what;
            EXPECT_EQ(reduced.image.pixels, test::reference_upscale(native.image, divisor).pixels) << what;
            EXPECT_EQ(reduced.visibility.width, internal.settings.width) << what;
            EXPECT_EQ(reduced.visibility.triangle, native.visibility.triangle) << what;
            EXPECT_EQ(reduced.stats.samples, native.stats.samples) << what;
        }
}

// One result reused across frames whose divisors change (its image and the upscale's buffers swap, shrink and grow)
// gives each frame the bytes a fresh render gives.
TEST(Render, aResultReusedAcrossResolutionDivisorsGivesEachFramesOwnBytes) {
    Scene scene = load_scene(kCorpus + "shadows_and_glass.yaml");
    RenderResult reused;
    for (int divisor : {2, 1, 4, 2, 4, 1, 2}) {
        scene.settings.resolution_divisor = divisor;
        render_into(scene, RenderOptions{}, reused);
        const RenderResult fresh = render(scene, RenderOptions{});
        EXPECT_EQ(reused.image.width, scene.settings.width) << divisor;
        EXPECT_EQ(reused.image.pixels, fresh.image.pixels) << "divisor " << divisor;
        EXPECT_EQ(reused.stats.samples, fresh.stats.samples) << divisor;
    }
}

// A backend of the test's own: the reference backend's drawing, every call recorded.
class RecordingBackend final : public RasterBackend {
public:
    mutable std::vector<std::string> calls;
    OpaqueDrawStats draw_opaque(const OpaqueDraw& draw, RenderResult& result) const override {
        calls.push_back("opaque");
        return raster_backend(RasterPath::reference).draw_opaque(draw, result);
    }
    void draw_depth(const FrameParams& frame, RenderWorkspace& workspace, float* view_depth) const override {
        calls.push_back("depth " + std::to_string(frame.width));
        raster_backend(RasterPath::reference).draw_depth(frame, workspace, view_depth);
    }
};

TEST(Render, aFrameOnABackendOfItsOwnDrawsTheShadowFacesFirstThenTheOpaqueFrameThenComposites) {
    Scene scene = load_scene(kCorpus + "shadows_and_glass.yaml");
    scene.settings.shadows.resolution = 64;
    const size_t shadowed = static_cast<size_t>(
        std::count_if(scene.lights.begin(), scene.lights.end(), [](const Light& l) { return l.shadows; }));
    ASSERT_GE(shadowed, 1u);
    const RecordingBackend backend;
    RenderResult recorded;
    render_frame(scene, RenderOptions{}, backend, recorded);
    std::vector<std::string> expected(6 * shadowed, "depth 64");
    expected.push_back("opaque");
    EXPECT_EQ(backend.calls, expected);
    EXPECT_GT(recorded.stats.transparent_fragments, 0u) << "the transparency pass ran after the opaque draw";
    RenderOptions reference;
    reference.path = RasterPath::reference;
    EXPECT_EQ(recorded.image.pixels, render(scene, reference).image.pixels);
}

TEST(Render, bothRenderersTimeRasterizationAndShadingApart) {
    const Scene scene = load_scene(kCorpus + "teapot.yaml");
    for (RasterPath path : {RasterPath::tiled, RasterPath::reference}) {
        RenderOptions options;
        options.path = path;
        const RenderStats stats = render(scene, options).stats;
        EXPECT_GT(stats.ms_raster, 0.0);
        EXPECT_GT(stats.ms_shade, 0.0) << "path " << static_cast<int>(path);
        EXPECT_LE(stats.ms_vertex + stats.ms_setup + stats.ms_raster + stats.ms_shade, stats.ms_total * 1.0001);
    }
}

TEST(Render, singleTriangleCoversItsProjectedArea) {
    // The triangle's exact screen area (projected by hand from the scene) matches the covered pixel count
    // within its perimeter's worth of boundary pixels.
    const Scene scene = load_scene(kCorpus + "single_triangle.yaml");
    const RenderResult result = render(scene, RenderOptions{});
    const glm::mat4 to_screen = viewport_matrix(scene.settings.width, scene.settings.height) *
                                projection_matrix(scene.camera, scene.settings.width, scene.settings.height) *
                                view_matrix(scene.camera);
    glm::vec2 p[3];
    for (int i = 0; i < 3; ++i) {
        const glm::vec4 c = to_screen * glm::vec4(scene.meshes[0].data->positions[i], 1.0f);
        p[i] = glm::vec2(c) / c.w;
    }
    const double area = 0.5 * std::fabs((p[1].x - p[0].x) * (p[2].y - p[0].y) - (p[1].y - p[0].y) * (p[2].x - p[0].x));
    const double perimeter = glm::length(p[1] - p[0]) + glm::length(p[2] - p[1]) + glm::length(p[0] - p[2]);
    EXPECT_NEAR(static_cast<double>(result.stats.covered_samples), area, perimeter / 2);
    // Vertex colours: near the first vertex (red) the pixel is mostly red.
    const glm::vec2 toward_red = p[0] + 0.1f * ((p[1] + p[2]) / 2.0f - p[0]);
    const uint8_t* red = pixel(result.image, int(toward_red.x), int(toward_red.y));
    EXPECT_GT(red[0], 150);
    EXPECT_LT(red[2], 80);
}

TEST(Render, interpenetratingTrianglesSwapOrderAlongTheirIntersection) {
    // Red is in front above the intersection line (y = 0 at the centre), blue below.
    const RenderResult result = render_corpus("interpenetrating.yaml");
    const uint8_t* above = pixel(result.image, 160, 110);
    const uint8_t* below = pixel(result.image, 160, 210);
    EXPECT_GT(above[0], 150);
    EXPECT_LT(above[2], 100);
    EXPECT_GT(below[2], 150);
    EXPECT_LT(below[0], 100);
}

TEST(Render, nearCrossingTriangleIsClippedNotDropped) {
    const RenderResult result = render_corpus("near_crossing.yaml");
    EXPECT_EQ(result.stats.clipped, 1u);
    EXPECT_GE(result.stats.rasterized, 2u);
    // The bottom row of the image looks at the floor just in front of the camera: the clipped part.
    const uint8_t* bottom = pixel(result.image, 200, 299);
    EXPECT_GT(bottom[0], 200);  // yellow floor, not sky
    EXPECT_LT(bottom[2], 100);
}

TEST(Render, perspectiveQuadInterpolatesInThreeDimensions) {
    // Every visible sample's barycentrics, applied to the triangle's world vertices, give a point on the ray
    // through that sample (perspective-correct), at the reported view depth.
    const Scene scene = load_scene(kCorpus + "perspective_quad.yaml");
    const RenderResult result = render(scene, RenderOptions{});
    const TransformedScene geometry = run_vertex_stage(scene, {true, false});
    const glm::mat4 view = view_matrix(scene.camera);
    const VisibilityBuffer& vis = result.visibility;
    int checked = 0;
    for (size_t i = 0; i < vis.size(); i += 997) {
        if (vis.triangle[i] == kNoTriangle) continue;
        const TriangleIndices& t = geometry.triangles[vis.triangle[i]];
        glm::vec3 world(0.0f);
        for (int k = 0; k < 3; ++k) world += vis.bary[i][k] * geometry.world_position[t.v[k]];
        const glm::vec3 in_view = glm::vec3(view * glm::vec4(world, 1.0f));
        EXPECT_NEAR(-in_view.z, vis.view_depth[i], 1e-3f * vis.view_depth[i]);
        ++checked;
    }
    EXPECT_GT(checked, 50);
}

TEST(Render, flatCubeShowsThreeFacesInThreeShades) {
    const RenderResult result = render_corpus("flat_cube.yaml");
    std::map<std::array<uint8_t, 3>, int> colours;
    for (int y = 0; y < result.image.height; y += 2)
        for (int x = 0; x < result.image.width; x += 2) {
            const uint8_t* p = pixel(result.image, x, y);
            ++colours[{p[0], p[1], p[2]}];
        }
    // Flat shading makes large regions of one exact colour: the background and at least three faces (each face is
    // two triangles lit separately at their centroids). Smooth shading would leave no colour this common.
    int large_regions = 0;
    for (const auto& [colour, count] : colours) large_regions += count >= 1000;
    EXPECT_GE(large_regions, 4);
}

}  // namespace
}  // namespace raster
