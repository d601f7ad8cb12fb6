// The extreme properties, each with an explicit expectation: near = 1e-6 with far = 1e9, vertices 2^20 pixels off
// screen, slivers of aspect 1e6, triangles under 1/256 px, vertices exactly on the near plane, w ~ 0, NaN and Inf
// coordinates, and scene extents near the float limits. Whole scenes at the depth and float limits, and the clip,
// tiling and setup checks on generators of extreme input.
#include <cmath>
#include <limits>
#include <string>

#include "properties/clip_checks.h"
#include "properties/depth_precision.h"
#include "properties/failure.h"
#include "properties/generators.h"
#include "properties/lens_projection.h"
#include "properties/printing.h"
#include "properties/property_registry.h"
#include "properties/reference/coverage_reference.h"
#include "properties/tiling_check.h"
#include "raster/core/errors.h"
#include "raster/scene/validation.h"

namespace raster::properties {
namespace {

// A camera at the origin looking down -z with a square image of 16 x 16 pixels, unlit.
Scene looking_down_negative_z(float fov, float near, float far, int samples) {
    Scene scene;
    scene.settings.width = scene.settings.height = 16;
    scene.settings.samples = samples;
    scene.settings.shading = ShadingMode::unlit;
    scene.camera.eye = glm::vec3(0.0f);
    scene.camera.target = {0.0f, 0.0f, -1.0f};
    scene.camera.up = {0.0f, 1.0f, 0.0f};
    scene.camera.fov_y_degrees = fov;
    scene.camera.near = near;
    scene.camera.far = far;
    return scene;
}

SceneMesh triangle_mesh(const std::array<glm::vec3, 3>& t) {
    SceneMesh mesh;
    mutable_data(mesh).positions = {t[0], t[1], t[2]};
    mutable_data(mesh).triangles = {{{0, 1, 2}}};
    return mesh;
}

// A quad at view depth w, twice as wide as a 90-degree view there.
SceneMesh quad_at(float w) {
    SceneMesh mesh;
    mutable_data(mesh).positions = {{-2 * w, -2 * w, -w}, {2 * w, -2 * w, -w}, {2 * w, 2 * w, -w}, {-2 * w, 2 * w, -w}};
    mutable_data(mesh).triangles = {{{0, 1, 2}}, {{0, 2, 3}}};
    return mesh;
}

bool same_bits(float a, float b) { return a == b || (std::isnan(a) && std::isnan(b)); }

}  // namespace

// Two fronto-parallel quads filling the view at view depths w1 < w2 anywhere in [1e-6, 1e9], w2 >= w1 (1 + 2^-19),
// rendered in either order: every sample shows the nearer quad, at view depth w1 within 2^-22 relative.
RASTER_RENDERER_PROPERTY(Extremes, nearOneMillionthAndFarOneBillionKeepTheNearerSurface) {
    const DepthPairCase c = *depth_pairs_over_extreme_range();
    RC_CLASSIFY(true, c.kind);
    Scene scene = looking_down_negative_z(90.0f, 1e-6f, 1e9f, 1);
    scene.meshes.push_back(quad_at(c.nearer_first ? c.near_depth : c.far_depth));
    scene.meshes.push_back(quad_at(c.nearer_first ? c.far_depth : c.near_depth));
    const uint32_t first_near_id = c.nearer_first ? 0 : 2;
    const RenderResult result = render_with(impl, scene);
    const VisibilityBuffer& v = result.visibility;
    for (size_t i = 0; i < v.size(); ++i) {
        const uint32_t id = v.triangle[i];
        if (id != first_near_id && id != first_near_id + 1)
            fail_case("sample " + std::to_string(i) + " shows " + (id == kNoTriangle ? std::string("nothing") : "triangle " + std::to_string(id)) +
                      ", not the quad at " + float_literal(c.near_depth) + " in front of the one at " + float_literal(c.far_depth));
        if (!(std::fabs(double(v.view_depth[i]) - c.near_depth) <= std::ldexp(double(c.near_depth), -22)))
            fail_case("sample " + std::to_string(i) + " reports view depth " + float_literal(v.view_depth[i]) + " for the quad at " +
                      float_literal(c.near_depth));
    }
    if (v.size() != 16u * 16u) fail_case("the visibility buffer has " + std::to_string(v.size()) + " samples");
}

// Vertices up to 2^20 px off screen: the clipped vertices satisfy the planes, and the drawn samples are exactly
// the in-frustum samples of the unclipped triangle outside the derived margin (clip_checks.h).
RASTER_DRAWING_PROPERTY(Extremes, verticesUpTo2To20PixelsOffScreenCoverTheirVisibleSamples) {
    const ClipCase c = *triangles_far_off_screen();
    RC_CLASSIFY(true, c.kind);
    check_clipped_vertices(impl, c);
    check_clip_then_rasterize(impl, c);
}

// Two slivers of aspect ~1e6 sharing their long edge (16384 px long at 16 sub-pixel bits, the fixed-point limit,
// or across a 32 px frame): exactly the reference's samples, and the shared edge's samples exactly once.
RASTER_RENDERER_PROPERTY(Extremes, sliversOfAspectOneMillionAreWatertightAndExact) {
    check_tiling(impl, *sliver_pairs());
}

// Triangles smaller than one sub-pixel unit (1/256 px at 8 bits), a few units, or under one square pixel, all at
// a sample: they cover exactly the reference's samples (often none, never a crash, and never dropped for being
// small when their snapped form holds a sample).
RASTER_RENDERER_PROPERTY(Extremes, trianglesSmallerThanASubPixelCoverExactlyTheReferenceSamples) {
    check_tiling(impl, *sub_pixel_triangles());
}

// One to three vertices exactly on the near plane (the rest inside): the triangle is not clipped, its near
// vertices get depth 1 within depth_error_at_near, and it covers exactly the reference's samples.
RASTER_DRAWING_PROPERTY(Extremes, verticesExactlyOnTheNearPlaneAreKeptWithDepthOne) {
    const LayeredCase c = *triangles_touching_the_near_plane();
    RC_CLASSIFY(true, c.kind);
    const Frame& frame = c.frame;
    const ClipTriangle t = project(impl, c).at(0);
    const ClippedPolygon polygon = impl.stages.clip(t.v[0], t.v[1], t.v[2], frame.volume);
    if (polygon.count != 3 || polygon.clipped)
        fail_case("a triangle with vertices on the near plane came back from clipping with " + std::to_string(polygon.count) +
                  " vertices" + (polygon.clipped ? ", marked clipped" : ""));
    std::vector<TriangleSetup> setups;
    impl.stages.setup(polygon, 0, frame_params(frame.width, frame.height, frame.snap_bits), setups);
    const float on_near = static_cast<float>(1.0 / static_cast<double>(frame.volume.near));
    const double bound = depth_error_at_near(frame.volume.near, frame.volume.far);
    for (const TriangleSetup& s : setups)
        for (int i = 0; i < 3; ++i)
            if (s.inv_w[i] == on_near && !(std::fabs(double(s.depth[i]) - 1.0) <= bound))
                fail_case("a vertex on the near plane has depth " + float_literal(s.depth[i]) + ", not 1 within " + double_literal(bound));
    const VisibilityBuffer visibility = rasterize_setups(impl, frame, setups);
    const reference::Point a = snapped(frame, t.v[0]), b = snapped(frame, t.v[1]), d = snapped(frame, t.v[2]);
    for (const Sample& s : samples_of(frame)) {
        const bool expected = reference::reference_covers(a, b, d, s.fixed);
        const bool actual = s.index < visibility.size() && visibility.triangle[s.index] != kNoTriangle;
        if (expected != actual)
            fail_case(describe(s) + " is " +
                      (actual ? "covered" : "not covered") + ", the reference says otherwise");
    }
}

// A vertex at w = 0, +-1e-40 (denormal), +-1e-30 or +-near 1e-7: every clipped vertex has w >= near, and the
// drawn samples are the in-frustum ones of the unclipped triangle outside the derived margin.
RASTER_DRAWING_PROPERTY(Extremes, wNearZeroIsClippedBeforeAnyDivide) {
    const ClipCase c = *triangles_with_w_near_zero();
    RC_CLASSIFY(true, c.kind);
    check_every_clipped_w_is_at_least_near(impl, c);
    check_clip_then_rasterize(impl, c);
}

// NaN or +-Inf in one to three clip coordinates: the clip stage returns nothing and no sample is covered; the same
// number in a scene's vertex makes validate_scene throw InputError. (Run under UBSan: no undefined behaviour.)
RASTER_DRAWING_PROPERTY(Extremes, nonFiniteCoordinatesAreRejectedCleanly) {
    const ClipCase c = *triangles_with_non_finite_coordinates();
    RC_CLASSIFY(true, c.kind);
    const ClippedPolygon polygon = impl.stages.clip(c.triangle.v[0], c.triangle.v[1], c.triangle.v[2], c.frame.volume);
    if (polygon.count != 0) fail_case("a triangle with " + c.kind + " came back from clipping with " + std::to_string(polygon.count) + " vertices");
    const VisibilityBuffer visibility = draw(impl, c.frame, {c.triangle});
    for (size_t i = 0; i < visibility.size(); ++i)
        if (visibility.triangle[i] != kNoTriangle) fail_case("a triangle with " + c.kind + " covers sample " + std::to_string(i));

    // The same number in a scene is an input error, not a rendering.
    float bad = 0.0f;
    for (const glm::vec4& v : c.triangle.v)
        for (int k = 0; k < 4; ++k)
            if (!std::isfinite(v[k])) bad = v[k];
    Scene scene = looking_down_negative_z(45.0f, 0.1f, 100.0f, 1);
    scene.meshes.push_back(triangle_mesh({glm::vec3(bad, 0.0f, -1.0f), glm::vec3(1.0f, 0.0f, -1.0f), glm::vec3(0.0f, 1.0f, -1.0f)}));
    try {
        validate_scene(scene);
    } catch (const InputError&) {
        return;
    }
    fail_case("validate_scene accepted a vertex at " + float_literal(bad));
}

// A scene scaled by 2^k (k up to 120: extents near 2e37; down to -100) renders bit for bit the same ids and
// barycentrics, with view depths scaled by exactly 2^k: every float operation on the way scales exactly while
// nothing overflows or goes subnormal (the generator's ranges are chosen for that, see
// generators/scene_extremes.cpp). And a triangle at +-3e38, whose clip coordinates overflow to Inf and NaN,
// changes nothing else and leaves every value in the visibility buffer finite.
RASTER_RENDERER_PROPERTY(Extremes, sceneExtentsNearFloatLimitsRenderExactlyScaled) {
    const ScaledSceneCase c = *scenes_scaled_towards_float_limits();
    RC_CLASSIFY(true, c.kind);
    auto scene_scaled_by = [&](int exponent) {
        Scene scene = looking_down_negative_z(45.0f, std::ldexp(c.near, exponent), std::ldexp(c.far, exponent), 4);
        std::array<glm::vec3, 3> t = c.triangle;
        for (glm::vec3& p : t) p = {std::ldexp(p.x, exponent), std::ldexp(p.y, exponent), std::ldexp(p.z, exponent)};
        scene.meshes.push_back(triangle_mesh(t));
        return scene;
    };
    const RenderResult base = render_with(impl, scene_scaled_by(0)), scaled = render_with(impl, scene_scaled_by(c.exponent));
    const VisibilityBuffer &a = base.visibility, &b = scaled.visibility;
    int covered = 0;
    for (size_t i = 0; i < a.size() && i < b.size(); ++i) {
        covered += a.triangle[i] != kNoTriangle;
        if (a.triangle[i] != b.triangle[i] ||
            (a.triangle[i] != kNoTriangle &&
             (a.bary[i] != b.bary[i] || !same_bits(std::ldexp(a.view_depth[i], c.exponent), b.view_depth[i]))))
            fail_case("sample " + std::to_string(i) + " changes when the scene is scaled by 2^" + std::to_string(c.exponent) +
                      ": triangle " + std::to_string(a.triangle[i]) + " -> " + std::to_string(b.triangle[i]) + ", depth " +
                      float_literal(a.view_depth[i]) + " -> " + float_literal(b.view_depth[i]));
    }
    RC_CLASSIFY(covered > 0, "covers samples");

    // Beyond the limits: a triangle whose clip coordinates overflow (to Inf, and to NaN where two overflowing
    // products of opposite sign meet in a row of the matrix) must change nothing.
    Scene plain = scene_scaled_by(0);
    plain.camera.target = {0.6f, 0.0f, -0.8f};
    Scene overflowing = plain;
    overflowing.meshes.push_back(triangle_mesh({glm::vec3(3e38f, -3e38f, -3e38f), glm::vec3(-3e38f, 3e38f, -3e38f),
                                                glm::vec3(3e38f, 3e38f, -1e38f)}));
    const RenderResult without = render_with(impl, plain), with = render_with(impl, overflowing);
    for (size_t i = 0; i < without.visibility.size(); ++i) {
        const VisibilityBuffer &p = without.visibility, &q = with.visibility;
        const bool finite = std::isfinite(q.view_depth[i]) && std::isfinite(q.bary[i].x) && std::isfinite(q.bary[i].y) &&
                            std::isfinite(q.bary[i].z);
        if (p.triangle[i] != q.triangle[i] || !finite ||
            (p.triangle[i] != kNoTriangle && (p.bary[i] != q.bary[i] || p.view_depth[i] != q.view_depth[i])))
            fail_case("a triangle at +-3e38 changes sample " + std::to_string(i) + ": triangle " + std::to_string(p.triangle[i]) +
                      " -> " + std::to_string(q.triangle[i]) + ", depth " + float_literal(q.view_depth[i]));
    }
}

}  // namespace raster::properties
