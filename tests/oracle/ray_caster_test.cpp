// The Embree oracle's visibility: the documented sample positions (the same as raster's), the scene's ids, exact
// barycentrics and view depth, planar near and far clipping, back-face culling, and the same output for any
// thread count.
#include "oracle/reference/ray_caster.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "oracle/reference/precision.h"
#include "oracle/reference/reference_geometry.h"
#include "oracle/reference/sample_positions.h"
#include "oracle/reference/scene_geometry.h"
#include "raster/core/conventions.h"
#include "raster/compat/scene_loader.h"
#include "raster/frame/render.h"
#include "raster/geometry/sample_pattern.h"
#include "raster/transform/camera_matrices.h"
#include "raster/transform/model_matrix.h"
#include "tests/support/oracle_test_scenes.h"

namespace raster::oracle {
namespace {

using testing::camera_at_origin;
using testing::reference_for;
using testing::scene_with_triangles;

const std::string kCorpus = std::string(RASTER_SOURCE_DIR) + "/corpus/scenes/";

SampleBuffer oracle_buffer(const Scene& scene, OracleOptions options = {}) {
    SampleBuffer out;
    render_oracle(scene, oracle_scene(scene), options, out);
    return out;
}

// The screen position of sample s of pixel (x, y), from the oracle's documented positions.
glm::dvec2 sample_screen(const Scene& scene, int x, int y, int s) {
    const std::vector<glm::dvec2> offsets =
        sample_offsets_on_grid(scene.settings.samples, scene.settings.pattern, scene.settings.snap_bits);
    return glm::dvec2(x, y) + offsets.at(static_cast<size_t>(s));
}

size_t covered(const SampleBuffer& buffer) {
    size_t n = 0;
    for (uint32_t id : buffer.triangle) n += id != kNoTriangle;
    return n;
}

// The same scene seen from a camera at the origin looking down -z, its vertices moved into view space in float by
// raster's view matrix: how the oracle saw the scenes the differential fuzzer found (it took raster's float view
// then), so that Embree gets exactly the float vertices it stumbled on.
Scene in_float_view_space(const Scene& scene) {
    Scene out = scene;
    out.camera.eye = glm::vec3(0.0f);
    out.camera.target = glm::vec3(0.0f, 0.0f, -1.0f);
    out.camera.up = glm::vec3(0.0f, 1.0f, 0.0f);
    for (SceneMesh& mesh : out.meshes) {
        const glm::mat4 model_view = view_matrix(scene.camera) * model_matrix(mesh.transform);
        for (glm::vec3& p : mutable_data(mesh).positions) p = glm::vec3(model_view * glm::vec4(p, 1.0f));
        mesh.transform = {};
    }
    return out;
}

// One sample where the oracle shows triangle 0 of a one-triangle scene: its index in the buffer, its screen
// position, and where it is, for messages.
struct OracleHit {
    size_t at;
    glm::dvec2 screen;
    std::string where;
};

// Every sample where the oracle shows triangle 0 of `scene`, with the scene's exact reference geometry.
std::vector<OracleHit> oracle_hits(const Scene& scene, const SampleBuffer& buffer) {
    std::vector<OracleHit> hits;
    for (int py = 0; py < buffer.height; ++py)
        for (int px = 0; px < buffer.width; ++px)
            for (int s = 0; s < buffer.samples; ++s) {
                const size_t at = buffer.index(px, py, s);
                if (buffer.triangle[at] != 0) continue;
                hits.push_back({at, sample_screen(scene, px, py, s),
                                std::to_string(px) + "," + std::to_string(py) + " sample " + std::to_string(s)});
            }
    return hits;
}

TEST(Oracle, itsDocumentedSamplePositionsAreRastersOnTheFixedPointGrid) {
    // Two transcriptions of the same documents: the oracle's and raster's (what its setup snaps samples to).
    int compared = 0;
    for (SamplePattern pattern : {SamplePattern::standard, SamplePattern::grid})
        for (int samples : {1, 2, 4, 8, 9, 16, 25, 64, 256})
            for (int snap_bits : {1, 4, 8, 12, 16}) {
                const std::vector<glm::dvec2> oracle = sample_offsets_on_grid(samples, pattern, snap_bits);
                const int fixed_bits = fixed_bits_for(snap_bits);
                const FixedSampleOffsets raster = fixed_sample_offsets(sample_offsets(samples, pattern), fixed_bits);
                ASSERT_EQ(oracle.size(), raster.x.size()) << samples;
                for (size_t s = 0; s < oracle.size(); ++s) {
                    EXPECT_EQ(oracle[s].x, std::ldexp(double(raster.x[s]), -fixed_bits)) << samples << " " << s;
                    EXPECT_EQ(oracle[s].y, std::ldexp(double(raster.y[s]), -fixed_bits)) << samples << " " << s;
                    ++compared;
                }
            }
    EXPECT_GT(compared, 1000);
}

TEST(Oracle, hitsCarryExactBarycentricsAndViewDepthAtTheDocumentedSamplePositions) {
    Scene scene = load_scene(kCorpus + "perspective_quad.yaml");
    const SampleBuffer buffer = oracle_buffer(scene);
    const ReferenceGeometry reference = reference_for(scene);
    ASSERT_EQ(buffer.samples, 4);
    size_t checked = 0;
    for (int y = 0; y < buffer.height; y += 7)
        for (int x = 0; x < buffer.width; x += 5)
            for (int s = 0; s < buffer.samples; ++s) {
                const size_t at = buffer.index(x, y, s);
                if (buffer.triangle[at] == kNoTriangle) continue;
                const ExactHit exact = reference.hit(buffer.triangle[at], sample_screen(scene, x, y, s));
                ASSERT_TRUE(exact.valid);
                EXPECT_NEAR(buffer.view_depth[at], exact.view_depth, 1e-5 * exact.view_depth);
                for (int k = 0; k < 3; ++k) EXPECT_NEAR(buffer.bary[at][k], exact.bary[k], 1e-4);
                ++checked;
            }
    EXPECT_GT(checked, 500u);
}

TEST(Oracle, triangleIdsAreTheScenesGlobalIds) {
    const SampleBuffer buffer = oracle_buffer(load_scene(kCorpus + "interpenetrating.yaml"));
    bool seen[2] = {false, false};
    for (uint32_t id : buffer.triangle) {
        if (id == kNoTriangle) continue;
        ASSERT_LT(id, 2u);
        seen[id] = true;
    }
    EXPECT_TRUE(seen[0] && seen[1]);
}

TEST(Oracle, theNearPlaneIsAPlaneNotASphere) {
    // A wall just in front of the near plane (view depth 0.999 < near = 1) and wider than the view: a spherical
    // near clip (t measured along unit rays) would keep its off-axis parts, where the distance exceeds 1.
    const float z = -0.999f;
    const std::vector<testing::Triangle> wall = {{{{-5, -5, z}, {5, -5, z}, {5, 5, z}}}, {{{-5, -5, z}, {5, 5, z}, {-5, 5, z}}}};
    Scene scene = scene_with_triangles(wall, camera_at_origin(90.0f, 1.0f, 10.0f), 64, 48);
    EXPECT_EQ(covered(oracle_buffer(scene)), 0u);
    // Just beyond the near plane it is seen everywhere.
    const float beyond = -1.001f;
    const std::vector<testing::Triangle> far_wall = {{{{-5, -5, beyond}, {5, -5, beyond}, {5, 5, beyond}}},
                                                      {{{-5, -5, beyond}, {5, 5, beyond}, {-5, 5, beyond}}}};
    scene = scene_with_triangles(far_wall, camera_at_origin(90.0f, 1.0f, 10.0f), 64, 48);
    EXPECT_EQ(covered(oracle_buffer(scene)), 64u * 48u);
}

TEST(Oracle, theFarPlaneIsAPlaneToo) {
    // A wall just beyond far = 10 is not seen anywhere; one just inside is seen everywhere, even at the image
    // corners where the distance along a unit ray is far more than 10.
    for (const auto& [z, expected] : {std::pair{-10.01f, 0u}, std::pair{-9.99f, 64u * 48u}}) {
        const std::vector<testing::Triangle> wall = {{{{-50, -50, z}, {50, -50, z}, {50, 50, z}}},
                                                     {{{-50, -50, z}, {50, 50, z}, {-50, 50, z}}}};
        EXPECT_EQ(covered(oracle_buffer(scene_with_triangles(wall, camera_at_origin(90.0f, 1.0f, 10.0f), 64, 48))),
                  expected)
            << z;
    }
}

TEST(Oracle, anOrthographicCameraCastsParallelRaysFromThePlaneThroughTheEye) {
    // A 4-unit-high view on 64 x 64 pixels: a 2 x 2 square covers the middle 32 x 32 pixels at any depth, and its
    // view depth is its distance from the plane through the eye (near 0).
    for (const float z : {-0.5f, -3.0f, -9.0f}) {
        const std::vector<testing::Triangle> square = {{{{-1, -1, z}, {1, -1, z}, {1, 1, z}}}, {{{-1, -1, z}, {1, 1, z}, {-1, 1, z}}}};
        Camera camera = camera_at_origin(90.0f, 0.0f, 10.0f);
        camera.projection = Projection::orthographic;
        camera.ortho_height = 4.0f;
        const Scene scene = scene_with_triangles(square, camera, 64, 64);
        const SampleBuffer buffer = oracle_buffer(scene);
        EXPECT_EQ(covered(buffer), 32u * 32u) << z;
        for (int y = 0; y < 64; ++y)
            for (int x = 0; x < 64; ++x) {
                const size_t at = buffer.index(x, y, 0);
                EXPECT_EQ(buffer.triangle[at] != kNoTriangle, x >= 16 && x < 48 && y >= 16 && y < 48) << x << ", " << y;
                if (buffer.triangle[at] != kNoTriangle) {
                    EXPECT_NEAR(buffer.view_depth[at], -z, 1e-6f);
                }
            }
    }
}

TEST(Oracle, backFacesAreLeftOutOnlyWhenTheSceneCulls) {
    const testing::Triangle counter_clockwise = {{{-1, -1, -3}, {1, -1, -3}, {0, 1, -3}}};
    const testing::Triangle clockwise = {{{-1, -1, -3}, {0, 1, -3}, {1, -1, -3}}};
    for (bool cull : {false, true}) {
        Scene front = scene_with_triangles({counter_clockwise}, camera_at_origin(), 40, 40);
        Scene back = scene_with_triangles({clockwise}, camera_at_origin(), 40, 40);
        front.settings.cull_backfaces = back.settings.cull_backfaces = cull;
        EXPECT_GT(covered(oracle_buffer(front)), 100u);
        EXPECT_EQ(covered(oracle_buffer(back)) == 0, cull);
        // raster agrees on which faces are front faces.
        EXPECT_EQ(render(back, RenderOptions{}).stats.covered_samples == 0, cull);
    }
}

TEST(Oracle, sameBuffersForAnyThreadCount) {
    Scene scene = load_scene(kCorpus + "teapot.yaml");
    scene.settings.width = scene.settings.height = 200;
    scene.settings.samples = 4;
    OracleOptions one, two, five;
    one.threads = 1;
    two.threads = 2;
    five.threads = 5;
    const SampleBuffer a = oracle_buffer(scene, one), b = oracle_buffer(scene, two), c = oracle_buffer(scene, five);
    for (const SampleBuffer* other : {&b, &c}) {
        ASSERT_EQ(a.size(), other->size());
        EXPECT_EQ(0, std::memcmp(a.triangle.data(), other->triangle.data(), a.size() * sizeof(uint32_t)));
        EXPECT_EQ(0, std::memcmp(a.bary.data(), other->bary.data(), a.size() * sizeof(glm::vec3)));
        EXPECT_EQ(0, std::memcmp(a.view_depth.data(), other->view_depth.data(), a.size() * sizeof(float)));
    }
}

TEST(Oracle, fastModeSeesTheSameSurfacesAwayFromEdges) {
    Scene scene = load_scene(kCorpus + "teapot.yaml");
    scene.settings.width = scene.settings.height = 200;
    OracleOptions fast;
    fast.mode = OracleMode::fast;
    const SampleBuffer robust_buffer = oracle_buffer(scene), fast_buffer = oracle_buffer(scene, fast);
    size_t same = 0;
    for (size_t i = 0; i < robust_buffer.size(); ++i) same += robust_buffer.triangle[i] == fast_buffer.triangle[i];
    EXPECT_GT(same, robust_buffer.size() * 999 / 1000);
    EXPECT_STREQ(to_string(OracleMode::fast), "fast");
    EXPECT_STREQ(to_string(OracleMode::robust), "robust");
}

// A needle (two vertices 0.02 apart, the third 28 away; found by the differential fuzzer): Embree's barycentrics
// drift from exact by more than a float rounding, because each of its edge values rounds on its own and their sum
// (twice the needle's tiny area) divides them. The derived bound (precision.h, "Embree's barycentrics") holds on
// every sample, and is needed: some samples are off by more than the float roundings allowed before it.
TEST(Oracle, embreesBarycentricsOnANeedleStayWithinTheirDerivedBound) {
    Scene scene = scene_with_triangles({{{{0x1.3ffe9p+3f, 0x1.4p+3f, 0x1.3fd8p+3f}, {10, 10, 10}, {10, -10, -10}}}},
                                       camera_at_origin(), 17, 32, 1);
    scene.camera.eye = {-0x1.3f464cp+3f, 0x1.aaa63p+1f, -0x1.61e1e2p+2f};
    scene.camera.target = glm::vec3(0.0f);
    scene.camera.up = {0x1.bdbdcp-2f, 0x1.b9c9c8p-2f, -0x1.1b1b1cp-1f};
    scene.camera.fov_y_degrees = 0x1.bfa3a4p+5f;
    scene.camera.near = 0x1.0624dep-10f;
    scene.camera.far = 0x1.dcd65p+29f;
    scene.settings.snap_bits = 12;
    scene = in_float_view_space(scene);
    const ReferenceGeometry reference = reference_for(scene);
    const SampleBuffer buffer = oracle_buffer(scene);
    const std::vector<OracleHit> hits = oracle_hits(scene, buffer);
    int beyond_roundings = 0;
    for (const OracleHit& hit : hits) {
        const glm::dvec3 exact = reference.hit(0, hit.screen).bary;
        const glm::dvec3 bound = reference.embree_barycentric_error(0, hit.screen);
        const glm::dvec3 error = glm::abs(glm::dvec3(buffer.bary[hit.at]) - exact);
        EXPECT_LE(error.x, bound.x) << hit.where;
        EXPECT_LE(error.y, bound.y) << hit.where;
        EXPECT_LE(error.z, bound.z) << hit.where;
        beyond_roundings += std::max({error.x, error.y, error.z}) > 2.0 * barycentric_rounding(0.0);
    }
    EXPECT_FALSE(hits.empty());
    EXPECT_GT(beyond_roundings, 0);
}

// A sliver seen almost edge-on (found by the differential fuzzer): Embree's t = T / den divides by twice its area
// seen along the ray, so its depth drifts by 0.3%. The derived bound (precision.h, "Embree's view depth") holds on
// every sample, and is needed: some samples are off by more than the float roundings allowed before it.
TEST(Oracle, embreesViewDepthOnASliverStaysWithinItsDerivedBound) {
    const float a = 0x1.337374p+3f, c = 0x1.8a0a08p+2f, d = -0x1.9b9bap+0f;
    Scene scene = scene_with_triangles({{{{a, a, a}, {c, c, 0x1.8a0818p+2f}, {d, d, d}}}},
                                       camera_at_origin(0x1.8620b8p+2f, 0x1.0624dep-10f, 10), 32, 32, 4);
    scene.camera.eye = {0x1.d0be08p+2f, c, c};
    scene.camera.target = glm::vec3(c);
    scene.settings.pattern = SamplePattern::grid;
    scene.settings.snap_bits = 4;
    scene = in_float_view_space(scene);
    const ReferenceGeometry reference = reference_for(scene);
    const SampleBuffer buffer = oracle_buffer(scene);
    const std::vector<OracleHit> hits = oracle_hits(scene, buffer);
    int beyond_roundings = 0;
    for (const OracleHit& hit : hits) {
        const double exact = reference.hit(0, hit.screen).view_depth;
        const double error = std::fabs(double(buffer.view_depth[hit.at]) - exact);
        EXPECT_LE(error, reference.embree_view_depth_error(0, hit.screen)) << hit.where;
        beyond_roundings += error > 2.0 * view_depth_rounding(0.0) * exact;
    }
    EXPECT_FALSE(hits.empty());
    EXPECT_GT(beyond_roundings, 0);
}

// Embree decides each edge's sign on its own (precision.h, "Embree's coverage"), so it can show a triangle where no
// single moved triangle reaches. Two scenes the differential fuzzer found: a needle along a line through the
// screen centre, hit by the centre ray beyond its tip; and a triangle whose three edges pass within float error of
// the eye, which is exactly seen edge-on outside the view and covers nothing. On both, every Embree hit is one the
// model allows, and some hits lie outside the exact triangle and beyond its edge band: the rule is needed.
TEST(Oracle, embreesCoverageStaysWhereItsEdgeByEdgeTestAllows) {
    Scene needle = scene_with_triangles(
        {{{{-10, -10, -10}, {-10, -10, -0x1.3ffffep+3f}, {-0x1.5f5f6p+0f, -0x1.5f5f6p+0f, -0x1.5f5f6p+0f}}}},
        camera_at_origin(0x1.7201bap+5f, 0x1.141416p+2f, 0x1.0df696p+12f), 23, 1, 1);
    needle.camera.eye = {-0x1.1b3f2p+0f, 0x1.5f81f4p+2f, -0x1.f85c5p+1f};
    needle.camera.target = glm::vec3(0.0f);
    needle.camera.up = {-0x1.a7365p-4f, 0x1.bc9c4p-4f, -0x1.c1336ap-1f};
    needle.settings.pattern = SamplePattern::grid;
    needle.settings.snap_bits = 11;
    const float e = 0x1.f0f0fp+1f;  // the eye's coordinates, and the vertices'
    Scene through_eye = scene_with_triangles({{{{e, e, -10}, {e, 0x1.f0f0e8p+1f, e}, {e, e, 0x1.61e1ep+0f}}}},
                                             camera_at_origin(0x1.f2fcfep+6f, 0x1.0624dep-10f, 100), 8, 16, 4);
    through_eye.camera.eye = glm::vec3(e);
    through_eye.camera.target = glm::vec3(0.0f);
    through_eye.camera.up = {0x1.88p-2f, -0x1.b93938p-1f, 0x1.8d8d9p-2f};
    through_eye.settings.pattern = SamplePattern::grid;
    through_eye.settings.snap_bits = 1;
    needle = in_float_view_space(needle);
    through_eye = in_float_view_space(through_eye);
    for (const Scene* scene : {&needle, &through_eye}) {
        const ReferenceGeometry reference = reference_for(*scene);
        const SampleBuffer buffer = oracle_buffer(*scene);
        const std::vector<OracleHit> hits = oracle_hits(*scene, buffer);
        int beyond_band = 0;
        for (const OracleHit& hit : hits) {
            EXPECT_TRUE(reference.embree_may_cover(0, hit.screen)) << hit.where;
            beyond_band += !reference.contains(0, hit.screen) &&
                           !(reference.boundary_distance(0, hit.screen) <= reference.polygon(0).radius);
        }
        EXPECT_FALSE(hits.empty()) << scene->camera.near;
        EXPECT_GT(beyond_band, 0) << scene->camera.near;
    }
}

}  // namespace
}  // namespace raster::oracle
