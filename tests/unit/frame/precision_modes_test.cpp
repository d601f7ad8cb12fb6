// The precision modes: each does what its name promises, and each cheaper mode shows its known failure on a case
// built to expose it (float edges crack, float and fixed24 depth lose a near-tie the reversed-Z buffer keeps, the
// guard band skips side clipping, hierarchical Z skips hidden work without changing a byte).
#include "raster/scene/precision_modes.h"

#include <algorithm>
#include <cmath>
#include <map>

#include <gtest/gtest.h>

#include "raster/core/conventions.h"
#include "raster/rasterize/per_sample.h"
#include "raster/rasterize/reference_rasterizer.h"
#include "raster/frame/render.h"
#include "raster/geometry/setup.h"

namespace raster {
namespace {

TEST(PrecisionModes, everyNameParsesBackToItsValue) {
    for (EdgeArithmetic v : {EdgeArithmetic::fixed, EdgeArithmetic::float32}) {
        EdgeArithmetic parsed{};
        ASSERT_TRUE(parse_edge_arithmetic(to_string(v), parsed));
        EXPECT_EQ(parsed, v);
    }
    for (DepthFormat v : {DepthFormat::reversed_z, DepthFormat::float_z, DepthFormat::fixed24}) {
        DepthFormat parsed{};
        ASSERT_TRUE(parse_depth_format(to_string(v), parsed));
        EXPECT_EQ(parsed, v);
    }
    Interpolation interpolation{};
    EXPECT_TRUE(parse_interpolation("affine", interpolation));
    EXPECT_EQ(interpolation, Interpolation::affine);
    Clipping clipping{};
    EXPECT_TRUE(parse_clipping("guard-band", clipping));
    EXPECT_EQ(clipping, Clipping::guard_band);
    DepthFormat unchanged = DepthFormat::float_z;
    EXPECT_FALSE(parse_depth_format("fixed32", unchanged));
    EXPECT_EQ(unchanged, DepthFormat::float_z);
    EXPECT_EQ(depth_format_names(), "reversed-z, float, fixed24");
}

TEST(DepthKey, largerIsNearerInEveryFormat) {
    for (DepthFormat format : {DepthFormat::reversed_z, DepthFormat::float_z, DepthFormat::fixed24}) {
        EXPECT_GT(depth_key(0.9, format), depth_key(0.1, format)) << to_string(format);
        EXPECT_GT(depth_key(1.0, format), depth_key(0.999, format)) << to_string(format);
    }
    EXPECT_EQ(depth_key(1.0, DepthFormat::float_z), 0.0);       // near: z = 0
    EXPECT_EQ(depth_key(0.0, DepthFormat::float_z), -1.0);      // far: z = 1
    EXPECT_EQ(depth_key(0.0, DepthFormat::fixed24), -kFixed24Levels);
    EXPECT_EQ(depth_key(0.25, DepthFormat::reversed_z), 0.25);
}

// Two triangles sharing an edge on a 16384-pixel screen at 16 snap bits (fixed-point coordinates near 2^30, so the
// float products dy * x keep 24 of their ~60 bits). Points of the fixed grid in a band across the shared edge are
// counted: exact edges cover each exactly once; float edges round the shared edge differently for each triangle.
struct SharedEdgeCount {
    int points = 0, not_once = 0;
};

SharedEdgeCount shared_edge_coverage(EdgeArithmetic edges) {
    constexpr int kSize = 16384;
    auto vertex = [](double px, double py) {
        return glm::vec4(static_cast<float>(2.0 * px / kSize - 1.0), static_cast<float>(1.0 - 2.0 * py / kSize), 0.5f, 1.0f);
    };
    const glm::dvec2 a(9000.3, 8000.7), b(11000.9, 9500.1), left(9500.2, 9900.4), right(10500.6, 7600.8);
    FrameParams params = frame_params(kSize, kSize, 16);
    params.edges = edges;
    std::vector<TriangleSetup> setups;
    for (const glm::dvec2& third : {left, right})
        setup_polygon(clip_triangle(vertex(a.x, a.y), vertex(b.x, b.y), vertex(third.x, third.y), ClipVolume{0.1f, 10.0f}),
                      0, params, setups);
    EXPECT_EQ(setups.size(), 2u);
    const int F = fixed_bits_for(16);
    const double scale = std::ldexp(1.0, F);
    SharedEdgeCount count;
    for (double t = 0.1; t < 0.9; t += 0.0007) {  // columns along the edge, away from its ends
        const int64_t X = static_cast<int64_t>((a.x + t * (b.x - a.x)) * scale);
        const int64_t Y_edge = static_cast<int64_t>((a.y + t * (b.y - a.y)) * scale);
        for (int64_t Y = Y_edge - 256; Y <= Y_edge + 256; ++Y) {
            const int n = covers(setups[0], X, Y) + covers(setups[1], X, Y);
            ++count.points;
            count.not_once += n != 1;
        }
    }
    return count;
}

TEST(EdgeArithmetic, fixedEdgesCoverASharedEdgeExactlyOnceAndFloatEdgesCrackOrDoubleIt) {
    const SharedEdgeCount fixed = shared_edge_coverage(EdgeArithmetic::fixed);
    const SharedEdgeCount rounded = shared_edge_coverage(EdgeArithmetic::float32);
    ASSERT_GT(fixed.points, 100000);
    EXPECT_EQ(fixed.not_once, 0);
    EXPECT_GT(rounded.not_once, 0) << "float edges matched exact edges on a case built to show their rounding";
}

TEST(Interpolation, affineIsLinearInScreenSpaceAndPerspectiveIsNot) {
    // One setup with very different w at its vertices; halfway along an edge in screen space.
    auto hit_at_midpoint = [](Interpolation interpolation) {
        FrameParams params = frame_params(64, 64, 8);
        params.interpolation = interpolation;
        const glm::vec4 a(-0.5f, -0.5f, 0.5f, 1.0f), b(0.5f * 10.0f, -0.5f * 10.0f, 0.5f, 10.0f), c(0.0f, 0.5f, 0.5f, 1.0f);
        ClippedPolygon polygon = clip_triangle(a, b, c, ClipVolume{0.1f, 100.0f});
        std::vector<TriangleSetup> setups;
        setup_polygon(polygon, 0, params, setups);
        const TriangleSetup& t = setups.at(0);
        // Screen midpoint of the edge between the original vertices a and b (exact on the fixed grid: both ends are).
        int ia = 0, ib = 0;
        for (int i = 0; i < 3; ++i) {
            if (t.bary[i].x == 1.0f) ia = i;
            if (t.bary[i].y == 1.0f) ib = i;
        }
        return interpolate_hit(t, (t.x[ia] + t.x[ib]) / 2, (t.y[ia] + t.y[ib]) / 2);
    };
    const SampleHit affine = hit_at_midpoint(Interpolation::affine), perspective = hit_at_midpoint(Interpolation::perspective);
    EXPECT_NEAR(affine.bary.x, 0.5, 1e-6);
    EXPECT_NEAR(affine.view_depth, 5.5, 1e-5);  // (1 + 10) / 2
    // Perspective-correct: 1/w is linear, so the weight of the far vertex is (1/10) / (1 + 1/10) = 1/11.
    EXPECT_NEAR(perspective.bary.y, 1.0 / 11.0, 1e-6);
    EXPECT_NEAR(perspective.view_depth, 2.0 / 1.1, 1e-5);
}

// Two parallel walls 0.05 apart at 500 units with near 0.01, the farther drawn first: the nearer must replace it.
// Their z/w differ by ~2e-9, under float's spacing near 1 (6e-8) and a 24-bit level; reversed-Z d ~ 2e-5 keeps it.
// A square wall of half-side `half` at view depth -z, facing the camera at the origin: two triangles.
SceneMesh square_wall(float half, float z) {
    SceneMesh mesh;
    mesh.source = "inline";
    mutable_data(mesh).positions = {{-half, -half, z}, {half, -half, z}, {half, half, z}, {-half, half, z}};
    mutable_data(mesh).triangles = {{{0, 1, 2}}, {{0, 2, 3}}};
    return mesh;
}

Scene two_walls(DepthFormat depth) {
    Scene scene;
    scene.path = "two walls";
    scene.settings.width = scene.settings.height = 32;
    scene.settings.shading = ShadingMode::unlit;
    scene.settings.modes.depth = depth;
    scene.camera.eye = glm::vec3(0.0f);
    scene.camera.target = {0.0f, 0.0f, -1.0f};
    scene.camera.near = 0.01f;
    scene.camera.far = 1000.0f;
    for (float z : {-500.05f, -500.0f}) scene.meshes.push_back(square_wall(400, z));
    return scene;
}

size_t samples_showing_the_far_wall(DepthFormat depth) {
    const RenderResult result = render(two_walls(depth), RenderOptions{});
    size_t far = 0;
    for (uint32_t id : result.visibility.triangle) far += id < 2;  // triangles 0 and 1 are the far wall
    return far;
}

TEST(DepthFormat, reversedZKeepsANearTieThatFloatZAndFixed24Lose) {
    EXPECT_EQ(samples_showing_the_far_wall(DepthFormat::reversed_z), 0u);
    EXPECT_GT(samples_showing_the_far_wall(DepthFormat::float_z), 0u);
    EXPECT_GT(samples_showing_the_far_wall(DepthFormat::fixed24), 0u);
}

TEST(Clipping, theGuardBandFactorKeepsEdgeFunctionsWithin64Bits) {
    EXPECT_EQ(guard_band_factor(800, 800, 8), kGuardBand);
    EXPECT_EQ(guard_band_factor(16384, 16384, 16), 1.0);  // no room: full clipping
    for (int size : {800, 4096, 8192, 16384})
        for (int bits : {4, 8, 12, 16}) {
            const double g = guard_band_factor(size, size, bits);
            const double extent = double(size) * std::ldexp(1.0, bits);
            EXPECT_GE(g, 1.0);
            EXPECT_LE(g * (g + 1.0) * 0.5 * extent * extent, std::ldexp(1.0, 60)) << size << " px, " << bits << " bits";
        }
}

TEST(Clipping, aGuardBandLeavesTrianglesThatReachOffScreenUnclipped) {
    Scene scene = two_walls(DepthFormat::reversed_z);
    // One wall larger than the view, so its triangles reach off screen.
    scene.meshes = {square_wall(600, -500)};
    const RenderResult full = render(scene, RenderOptions{});
    scene.settings.modes.clipping = Clipping::guard_band;
    const RenderResult guard = render(scene, RenderOptions{});
    EXPECT_EQ(full.stats.clipped, 2u);
    EXPECT_EQ(guard.stats.clipped, 0u);
    EXPECT_EQ(guard.image.pixels, full.image.pixels);
    EXPECT_EQ(guard.stats.covered_samples, 32u * 32u);
}

// Layers of full-screen walls drawn nearest first: everything after the first is hidden.
TEST(HierarchicalZ, skipsHiddenBlocksWithoutChangingAByte) {
    Scene scene = two_walls(DepthFormat::reversed_z);
    scene.meshes.clear();
    scene.settings.width = scene.settings.height = 96;  // not a multiple of the tile: partial blocks too
    scene.settings.samples = 4;
    for (int layer = 0; layer < 8; ++layer) scene.meshes.push_back(square_wall(9, -2.0f - static_cast<float>(layer)));
    RenderOptions options;
    const RenderResult on = render(scene, options);
    scene.settings.modes.hierarchical_z = false;
    const RenderResult off = render(scene, options);
    EXPECT_EQ(on.image.pixels, off.image.pixels);
    EXPECT_EQ(on.visibility.triangle, off.visibility.triangle);
    EXPECT_GT(on.stats.hidden_blocks, 0u);
    EXPECT_EQ(off.stats.hidden_blocks, 0u);
    // Drawn farthest first, nothing is hidden when drawn: hierarchical Z has nothing to skip.
    std::reverse(scene.meshes.begin(), scene.meshes.end());
    scene.settings.modes.hierarchical_z = true;
    EXPECT_EQ(render(scene, options).stats.hidden_blocks, 0u);
}

}  // namespace
}  // namespace raster
