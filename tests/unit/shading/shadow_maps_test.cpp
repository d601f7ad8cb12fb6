// Shadow maps: the cube faces' convention, the map's answer under an occluder and beside it, the receiver-plane
// bias against a brute-force reference, no acne at the defaults, percentage-closer fractions, and both renderers
// drawing the same maps.
#include "raster/frame/shadow_pass.h"

#include <cmath>
#include <limits>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "raster/transform/cube_faces.h"
#include "raster/frame/render.h"
#include "raster/geometry/setup_table.h"
#include "raster/geometry/vertex_stage.h"
#include "tests/support/quad_meshes.h"

namespace raster {
namespace {

using test_support::quad_mesh;

// A floor at y = 0 reaching `extent` each way and, unless extent_only, a 1 x 1 square at y = 1 above the origin,
// lit by a light at `light` that casts shadows.
Scene floor_scene(const glm::vec3& light, float extent, bool occluder = true) {
    Scene scene;
    scene.settings.shading = ShadingMode::blinn_phong;
    scene.lights.push_back({light, glm::vec3(1.0f), 1.0f, false, true});
    scene.meshes.push_back(quad_mesh({-extent, 0, -extent}, {-extent, 0, extent}, {extent, 0, extent}, {extent, 0, -extent}));
    if (occluder)
        scene.meshes.push_back(quad_mesh({-0.5f, 1, -0.5f}, {-0.5f, 1, 0.5f}, {0.5f, 1, 0.5f}, {0.5f, 1, -0.5f}));
    return scene;
}

ShadowMaps maps_of(const Scene& scene, RasterPath path = RasterPath::tiled) {
    const TransformedScene geometry = run_vertex_stage(scene, vertex_stage_needs(scene.settings.shading));
    return render_shadow_maps(scene, geometry.world_position, raster_backend(path), 2);
}

const glm::vec3 kUp(0.0f, 1.0f, 0.0f);

TEST(CubeFaces, areRightHandedUnitFramesAndEveryDirectionLandsOnItsFace) {
    for (int f = 0; f < kCubeFaces; ++f) {
        const CubeFace& face = cube_face(f);
        EXPECT_EQ(face.right, glm::cross(face.axis, face.up)) << f;
        EXPECT_EQ(glm::dot(face.axis, face.up), 0.0f) << f;
        EXPECT_EQ(glm::length(face.axis), 1.0f) << f;
        EXPECT_EQ(cube_face_of(face.axis * 3.0f), f) << f;
    }
    for (float x = -1.0f; x <= 1.0f; x += 0.25f)
        for (float y = -1.0f; y <= 1.0f; y += 0.25f)
            for (float z = -1.0f; z <= 1.0f; z += 0.25f) {
                const glm::vec3 d(x, y, z);
                if (d == glm::vec3(0.0f)) continue;
                const CubeFace& face = cube_face(cube_face_of(d));
                const float depth = glm::dot(face.axis, d);
                ASSERT_GT(depth, 0.0f);
                EXPECT_LE(std::fabs(glm::dot(face.right, d) / depth), 1.0f);
                EXPECT_LE(std::fabs(glm::dot(face.up, d) / depth), 1.0f);
            }
    EXPECT_EQ(cube_face_of({1, 1, 1}), 0);  // ties go to x, then y
    EXPECT_EQ(cube_face_of({0, -2, 2}), 3);
}

TEST(ShadowMaps, darkenWhatTheOccluderHidesAndNothingElse) {
    // Light at height 4 over a square at height 1: its shadow on the floor is the square scaled by 4 / 3.
    const Scene scene = floor_scene({0, 4, 0}, 5.0f);
    const ShadowMaps maps = maps_of(scene);
    ASSERT_TRUE(maps.casts(0));
    for (float x = -3.0f; x <= 3.0f; x += 0.05f)
        for (float z = -3.0f; z <= 3.0f; z += 0.3f) {
            const float reach = std::max(std::fabs(x), std::fabs(z));
            const float visible = maps.visibility(0, {x, 0, z}, kUp);
            if (reach < 0.6f) {
                EXPECT_EQ(visible, 0.0f) << x << " " << z;
            }
            if (reach > 0.75f) {
                EXPECT_EQ(visible, 1.0f) << x << " " << z;
            }
        }
    // The occluder's own top faces the light: lit.
    EXPECT_EQ(maps.visibility(0, {0.2f, 1.0f, 0.1f}, kUp), 1.0f);
}

TEST(ShadowMaps, filterTheEdgeInNinthsWithPcf3) {
    Scene scene = floor_scene({0, 4, 0}, 5.0f);
    scene.settings.shadows.pcf = 3;
    const ShadowMaps maps = maps_of(scene);
    int partial = 0;
    for (float x = 0.55f; x <= 0.8f; x += 0.002f) {
        const float visible = maps.visibility(0, {x, 0, 0.1f}, kUp);
        const float ninths = visible * 9.0f;
        EXPECT_EQ(ninths, std::round(ninths)) << x;
        partial += visible > 0.0f && visible < 1.0f;
    }
    EXPECT_GT(partial, 0);
}

TEST(ShadowMaps, haveNoAcneAtTheDefaultsEvenAtGrazingAnglesAndPlentyWithoutBias) {
    // No occluder: the floor, lit from just above it, out to 40 times the light's height.
    Scene scene = floor_scene({0, 1, 0}, 40.0f, false);
    const ShadowMaps maps = maps_of(scene);
    int shadowed = 0, points = 0;
    for (float x = -39.0f; x <= 39.0f; x += 0.37f)
        for (float z = -39.0f; z <= 39.0f; z += 1.3f, ++points) shadowed += maps.visibility(0, {x, 0, z}, kUp) < 1.0f;
    EXPECT_EQ(shadowed, 0) << "of " << points;

    scene.settings.shadows.bias = 0.0f;
    scene.settings.shadows.slope_bias = 0.0f;
    const ShadowMaps unbiased = maps_of(scene);
    shadowed = 0;
    for (float x = -39.0f; x <= 39.0f; x += 0.37f)
        for (float z = -39.0f; z <= 39.0f; z += 1.3f) shadowed += unbiased.visibility(0, {x, 0, z}, kUp) < 1.0f;
    EXPECT_GT(shadowed, points / 10);
}

TEST(ShadowBias, isTheConstantPartPlusThePlanesDropAcrossTheFilterFoundByBruteForce) {
    ShadowSettings settings;
    settings.resolution = 64;
    settings.pcf = 3;
    const CubeFace& face = cube_face(0);  // +x
    // A plane through the point (3, 0.4, -0.7) (relative to the light) tilted towards the light.
    const glm::dvec3 point(3.0, 0.4, -0.7), normal = glm::normalize(glm::dvec3(-1.0, 0.8, 0.3));
    const double depth = point.x, s = point.z / depth, t = point.y / depth;  // right = +z, up = +y on +x
    const float bias = shadow_bias(settings, face, float(depth), float(s), float(t), glm::vec3(normal),
                                   float(glm::dot(normal, point)));
    // The reference: the plane's depth over a fine grid of the square of half-side 1.5 texels (3 / 64 in face
    // coordinates), nearest value.
    const double reach = 1.5 * 2.0 / 64.0;
    double nearest = depth;
    for (int i = 0; i <= 200; ++i)
        for (int j = 0; j <= 200; ++j) {
            const glm::dvec3 direction(1.0, t + reach * (j / 100.0 - 1.0), s + reach * (i / 100.0 - 1.0));
            nearest = std::min(nearest, glm::dot(normal, point) / glm::dot(normal, direction));
        }
    const double expected = settings.bias * depth + settings.slope_bias * (depth - nearest);
    EXPECT_NEAR(bias, expected, 1e-5 * depth);
    EXPECT_GT(depth - nearest, 0.01);  // the slope term is really there

    // Facing the light head-on, only the constant part is left; edge-on, the drop is capped at the depth.
    EXPECT_FLOAT_EQ(shadow_bias(settings, face, 2.0f, 0.0f, 0.0f, {-1, 0, 0}, -2.0f), settings.bias * 2.0f);
    EXPECT_FLOAT_EQ(shadow_bias(settings, face, 2.0f, 0.0f, 0.0f, {0, 1, 0}, 0.0f),
                    settings.bias * 2.0f + settings.slope_bias * 2.0f);
}

TEST(ShadowMaps, areTheSameFromTheTiledAndTheReferenceRasterizer) {
    Scene scene = floor_scene({0.3f, 2.5f, -0.4f}, 5.0f);
    scene.settings.shadows.resolution = 96;
    const ShadowMaps tiled = maps_of(scene, RasterPath::tiled), reference = maps_of(scene, RasterPath::reference);
    EXPECT_EQ(tiled.cube(0).depth, reference.cube(0).depth);
    size_t surfaces = 0;
    for (float d : tiled.cube(0).depth) surfaces += d != std::numeric_limits<float>::infinity();
    EXPECT_GT(surfaces, tiled.cube(0).depth.size() / 10);
}

// A grid of 2 n^2 triangles lying at height y over [x0, x0 + size] x [z0, z0 + size].
SceneMesh level_grid(int n, float y, float x0, float z0, float size, float opacity) {
    SceneMesh grid = test_support::grid_mesh(n, glm::vec3(0.5f), opacity);
    for (glm::vec3& p : mutable_data(grid).positions)
        p = glm::vec3(x0 + 0.5f * size * (p.x + 1.0f), y, z0 + 0.5f * size * (p.y + 1.0f));
    return grid;
}

// Over several of the front end's chunks, with a transparent grid's triangles in two of them: both renderers draw
// the map that the opaque triangles alone give.
TEST(ShadowMaps, overManyChunksAreTheSameFromBothRasterizersAndLeaveOutTheTransparentTriangles) {
    Scene scene = floor_scene({0.2f, 4.0f, 0.1f}, 5.0f, /*occluder=*/false);
    scene.settings.shadows.resolution = 64;
    scene.meshes.push_back(level_grid(50, 1.0f, -1.5f, -0.5f, 1.0f, 1.0f));  // opaque, triangles 2..5001
    scene.meshes.push_back(level_grid(50, 2.0f, 0.5f, -0.5f, 1.0f, 0.5f));   // transparent, 5002..10001
    scene.meshes.push_back(level_grid(10, 1.5f, -0.5f, 1.0f, 1.0f, 1.0f));   // opaque, in the third chunk
    ASSERT_GT(triangle_count(scene), 2 * kSetupChunkTriangles);
    const ShadowMaps tiled = maps_of(scene, RasterPath::tiled), reference = maps_of(scene, RasterPath::reference);
    Scene opaque_only = scene;
    opaque_only.meshes.erase(opaque_only.meshes.begin() + 2);
    EXPECT_EQ(tiled.cube(0).depth, reference.cube(0).depth);
    EXPECT_EQ(tiled.cube(0).depth, maps_of(opaque_only).cube(0).depth);
    EXPECT_EQ(tiled.visibility(0, {-1.0f, 0.0f, 0.0f}, kUp), 0.0f);  // under the first opaque grid
    EXPECT_EQ(tiled.visibility(0, {0.0f, 0.0f, 1.8f}, kUp), 0.0f);   // under the last one
    EXPECT_EQ(tiled.visibility(0, {1.0f, 0.0f, 0.0f}, kUp), 1.0f);   // under the transparent one
}

TEST(ShadowMaps, areBuiltOnlyForTheLightsThatCastShadows) {
    Scene scene = floor_scene({0, 4, 0}, 5.0f);
    scene.lights.push_back({{1, 4, 0}, glm::vec3(1.0f), 1.0f, false, false});
    const ShadowMaps maps = maps_of(scene);
    EXPECT_TRUE(maps.casts(0));
    EXPECT_FALSE(maps.casts(1));
    EXPECT_EQ(maps.visibility(1, {0, 0, 0}, kUp), 1.0f);
    scene.lights[0].shadows = false;
    EXPECT_TRUE(maps_of(scene).empty());
}

// In every lit mode the floor darkens where the square hides the light, and only there (a byte of rounding aside:
// flat and Gouraud keep a shadowed light's terms apart, which sums them in another order).
TEST(ShadowedRender, darkensTheShadowInEveryLitModeAndNothingElse) {
    Scene scene = floor_scene({0, 4, 0}, 5.0f);
    scene.settings.width = 120;
    scene.settings.height = 90;
    scene.camera.eye = {0.5f, 3.0f, 4.0f};
    scene.camera.target = {0.0f, 0.0f, 0.0f};
    for (ShadingMode mode : {ShadingMode::flat, ShadingMode::gouraud, ShadingMode::phong, ShadingMode::blinn_phong,
                             ShadingMode::cel, ShadingMode::gooch}) {
        scene.settings.shading = mode;
        scene.lights[0].shadows = true;
        const RenderResult shadowed = render(scene, RenderOptions{});
        scene.lights[0].shadows = false;
        const RenderResult lit = render(scene, RenderOptions{});
        int inside = 0, outside = 0;
        for (int y = 0; y < scene.settings.height; ++y)
            for (int x = 0; x < scene.settings.width; ++x) {
                const size_t at = shadowed.visibility.index(x, y, 0);
                if (shadowed.visibility.triangle[at] > 1) continue;  // not the floor
                const glm::vec3& b = shadowed.visibility.bary[at];
                const auto& p = scene.meshes[0].data->positions;
                const uint32_t* v = scene.meshes[0].data->triangles[shadowed.visibility.triangle[at]].v;
                const glm::vec3 point = b.x * p[v[0]] + b.y * p[v[1]] + b.z * p[v[2]];
                const float reach = std::max(std::fabs(point.x), std::fabs(point.z));
                const uint8_t *dark = shadowed.image.at(x, y), *bright = lit.image.at(x, y);
                if (reach < 0.6f) {
                    ++inside;
                    EXPECT_LT(dark[0] + dark[1] + dark[2], bright[0] + bright[1] + bright[2]) << to_string(mode);
                } else if (reach > 0.75f) {
                    ++outside;
                    for (int c = 0; c < 3; ++c) EXPECT_LE(std::abs(dark[c] - bright[c]), 1) << to_string(mode);
                }
            }
        EXPECT_GT(inside, 50) << to_string(mode);
        EXPECT_GT(outside, 500) << to_string(mode);
    }
}

}  // namespace
}  // namespace raster
