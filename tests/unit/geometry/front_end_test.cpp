// The front end's set-up gives, triangle by triangle, what the clip and setup stages give run one triangle at a
// time: with its vertices projected once for the unclipped triangles, in every precision mode; and it sets the
// transparent triangles' setups aside.
#include "raster/geometry/front_end.h"

#include <gtest/gtest.h>

#include "raster/compat/scene_loader.h"
#include "raster/geometry/sample_pattern.h"

namespace raster {
namespace {

const std::string kCorpus = std::string(RASTER_SOURCE_DIR) + "/corpus/scenes/";

// The definition: each triangle culled, clipped and set up on its own by the stages.
std::vector<TriangleSetup> one_triangle_at_a_time(const TransformedScene& geometry, const FrameParams& frame,
                                                  bool cull, size_t& clipped) {
    std::vector<TriangleSetup> setups;
    clipped = 0;
    for (size_t tri = 0; tri < geometry.triangles.size(); ++tri) {
        const TriangleIndices& v = geometry.triangles[tri];
        const glm::vec4 &a = geometry.clip[v.v[0]], &b = geometry.clip[v.v[1]], &c = geometry.clip[v.v[2]];
        if (cull && !faces_front(a, b, c)) continue;
        const ClippedPolygon polygon = clip_triangle(a, b, c, frame.clip);
        clipped += polygon.clipped;
        setup_polygon(polygon, static_cast<uint32_t>(tri), frame, setups);
    }
    return setups;
}

void expect_same_setup(const TriangleSetup& got, const TriangleSetup& want, size_t i) {
    SCOPED_TRACE("setup " + std::to_string(i) + ", triangle " + std::to_string(want.triangle_id));
    ASSERT_EQ(got.triangle_id, want.triangle_id);
    for (int k = 0; k < 3; ++k) {
        EXPECT_EQ(got.x[k], want.x[k]);
        EXPECT_EQ(got.y[k], want.y[k]);
        EXPECT_EQ(got.a[k], want.a[k]);
        EXPECT_EQ(got.b[k], want.b[k]);
        EXPECT_EQ(got.c[k], want.c[k]);
        EXPECT_EQ(got.bias[k], want.bias[k]);
        EXPECT_EQ(got.depth[k], want.depth[k]);
        EXPECT_EQ(got.inv_w[k], want.inv_w[k]);
        EXPECT_EQ(got.vertex_depth[k], want.vertex_depth[k]);
        EXPECT_EQ(got.bary[k], want.bary[k]);
    }
    EXPECT_EQ(got.area2, want.area2);
    EXPECT_EQ(got.inv_area2, want.inv_area2);
    EXPECT_EQ(got.min_x, want.min_x);
    EXPECT_EQ(got.max_x, want.max_x);
    EXPECT_EQ(got.min_y, want.min_y);
    EXPECT_EQ(got.max_y, want.max_y);
    EXPECT_EQ(got.affine, want.affine);
    EXPECT_EQ(got.depth_fixed24, want.depth_fixed24);
}

// The teapot from close up, so that the near plane and the sides cut it: some triangles are clipped, most not.
Scene close_teapot(const PrecisionModes& modes) {
    Scene scene = load_scene(kCorpus + "teapot.yaml");
    scene.camera.eye = glm::vec3(0.5f, 2.0f, 5.5f);
    scene.camera.near = 4.2f;
    scene.settings.width = 300;
    scene.settings.height = 200;
    scene.settings.modes = modes;
    return scene;
}

TEST(FrontEnd, setsUpEveryTriangleAsTheClipAndSetupStagesDoOneAtATime) {
    const PrecisionModes variants[] = {
        {},
        {EdgeArithmetic::float32, Interpolation::affine, DepthFormat::fixed24, Clipping::guard_band, true},
        {EdgeArithmetic::fixed, Interpolation::perspective, DepthFormat::float_z, Clipping::full, true},
    };
    for (const PrecisionModes& modes : variants)
        for (bool cull : {false, true}) {
            const Scene scene = close_teapot(modes);
            const TransformedScene geometry = run_vertex_stage(scene, vertex_stage_needs(scene.settings.shading));
            const FrameParams frame = frame_params_for(scene, sample_offsets(1, SamplePattern::standard), 2);
            SetupCounts stats;
            const std::vector<TriangleSetup> got = set_up_triangles(geometry, frame, cull, &stats);
            size_t clipped = 0;
            const std::vector<TriangleSetup> want = one_triangle_at_a_time(geometry, frame, cull, clipped);
            EXPECT_GT(clipped, 0u);
            EXPECT_GT(want.size(), clipped * 4) << "most triangles are not clipped";
            EXPECT_EQ(stats.clipped, clipped);
            EXPECT_EQ(stats.rasterized, want.size());
            ASSERT_EQ(got.size(), want.size());
            for (size_t i = 0; i < got.size(); ++i) expect_same_setup(got[i], want[i], i);
        }
}

TEST(FrontEnd, setsTheTransparentTrianglesSetupsAsideInDrawOrderAndKeepsTheRestInPlace) {
    const Scene scene = close_teapot({});
    const TransformedScene geometry = run_vertex_stage(scene, vertex_stage_needs(scene.settings.shading));
    const FrameParams frame = frame_params_for(scene, sample_offsets(1, SamplePattern::standard), 2);
    const std::vector<TriangleSetup> all = set_up_triangles(geometry, frame, false);
    std::vector<uint8_t> transparent(geometry.triangles.size(), 0);
    for (size_t tri = 0; tri < transparent.size(); tri += 3) transparent[tri] = 1;
    FrontEndSetups out;
    const SetupCounts counts = set_up_triangles_into(geometry, frame, false, transparent, out);
    EXPECT_EQ(counts.rasterized, all.size()) << "counted before the split";
    std::vector<TriangleSetup> opaque;
    concatenate_setups(out.setup_chunks, 2, opaque);
    size_t next_opaque = 0, next_transparent = 0;
    for (size_t i = 0; i < all.size(); ++i) {
        if (transparent[all[i].triangle_id]) {
            ASSERT_LT(next_transparent, out.transparent_setups.size());
            expect_same_setup(out.transparent_setups[next_transparent++], all[i], i);
        } else {
            ASSERT_LT(next_opaque, opaque.size());
            expect_same_setup(opaque[next_opaque++], all[i], i);
        }
    }
    EXPECT_EQ(next_opaque, opaque.size());
    EXPECT_EQ(next_transparent, out.transparent_setups.size());
    EXPECT_GT(next_transparent, 100u);
}

}  // namespace
}  // namespace raster
