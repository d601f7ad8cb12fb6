// The oracle's shadow model against raster's shadow code and against its own derivations: the faces transcribed
// as raster has them, the lookup's intervals holding raster's float face, texels and reference depth, boundary
// edges where silhouettes are, and the verdicts over a receiver swept across a shadow's edge, an occluder within the
// bias and a point lit in full: raster's visibility always allowed, and the open band as narrow as the map's own
// footprint makes it.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "oracle/reference/shadow_faces.h"
#include "oracle/reference/shadow_index.h"
#include "oracle/reference/shadow_oracle.h"
#include "oracle/reference/shadow_precision.h"
#include "raster/transform/cube_faces.h"
#include "raster/frame/shadow_pass.h"
#include "raster/geometry/vertex_stage.h"
#include "tests/support/quad_meshes.h"

namespace raster::oracle {
namespace {

TEST(ShadowFaces, areTheReadmesTableAsRasterHasIt) {
    for (int f = 0; f < kShadowFaces; ++f) {
        EXPECT_EQ(glm::vec3(shadow_face(f).axis), cube_face(f).axis) << f;
        EXPECT_EQ(glm::vec3(shadow_face(f).up), cube_face(f).up) << f;
        EXPECT_EQ(glm::vec3(shadow_face(f).right), cube_face(f).right) << f;
    }
    std::mt19937 rng(5);
    std::uniform_int_distribution<int> coordinate(-3, 3);  // small integers: many ties
    for (int i = 0; i < 2000; ++i) {
        const glm::vec3 d(coordinate(rng), coordinate(rng), coordinate(rng));
        if (d == glm::vec3(0.0f)) continue;
        const std::vector<int> faces = possible_faces(Interval3(glm::dvec3(d)));
        ASSERT_EQ(faces.size(), 1u) << d.x << " " << d.y << " " << d.z;
        EXPECT_EQ(faces[0], cube_face_of(d));
    }
    // A box across the tie between x and z holds both faces.
    const std::vector<int> both = possible_faces({Interval(2.0, 2.1), Interval(0.0), Interval(-2.05, -1.95)});
    EXPECT_EQ(both, (std::vector<int>{0, 5}));
}

// raster's own lookup of a point, in float as ShadowMaps::visibility does it.
struct RasterLookup {
    int face, column, row;
    float x, y, reference;
};
RasterLookup raster_lookup(const ShadowSettings& settings, const glm::vec3& light, const glm::vec3& point,
                           const glm::vec3& normal) {
    const glm::vec3 d = point - light;
    RasterLookup out;
    out.face = cube_face_of(d);
    const CubeFace& face = cube_face(out.face);
    const float depth = glm::dot(face.axis, d);
    const float s = glm::dot(face.right, d) / depth, t = glm::dot(face.up, d) / depth;
    out.reference = depth - shadow_bias(settings, face, depth, s, t, normal, glm::dot(normal, d));
    const float half = 0.5f * static_cast<float>(settings.resolution);
    out.x = (s + 1.0f) * half;
    out.y = (1.0f - t) * half;
    out.column = static_cast<int>(std::floor(out.x));
    out.row = static_cast<int>(std::floor(out.y));
    return out;
}

TEST(ShadowLookups, holdRastersFaceTexelsAndReferenceDepthAndAreTight) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f), far(-40.0f, 40.0f);
    std::vector<double> widths;
    for (int i = 0; i < 20000; ++i) {
        ShadowSettings settings;
        settings.resolution = 64 << (i % 5);
        settings.pcf = 1 + 2 * (i % 3);
        const glm::vec3 light(far(rng), far(rng), far(rng)), point(far(rng), far(rng), far(rng));
        glm::vec3 normal(unit(rng), unit(rng), unit(rng));
        if (!(glm::length(normal) > 0.1f)) continue;
        normal = glm::normalize(normal);
        const RasterLookup raster = raster_lookup(settings, light, point, normal);
        const std::vector<ShadowLookup> lookups =
            shadow_lookups(settings, glm::dvec3(light), Interval3(glm::dvec3(point)), Interval3(glm::dvec3(normal)));
        const ShadowLookup* mine = nullptr;
        for (const ShadowLookup& l : lookups)
            if (l.face == raster.face) mine = &l;
        ASSERT_NE(mine, nullptr) << "raster's face is not among the possible ones";
        EXPECT_TRUE(mine->x.contains(raster.x) && mine->y.contains(raster.y));
        const int n = settings.resolution;
        const double column = std::clamp(raster.column, 0, n - 1) + 0.5, row = std::clamp(raster.row, 0, n - 1) + 0.5;
        EXPECT_TRUE(mine->taps.x0 <= column && column <= mine->taps.x1 && mine->taps.y0 <= row && row <= mine->taps.y1);
        EXPECT_TRUE(mine->reference.contains(raster.reference))
            << raster.reference << " not in [" << mine->reference.lo << ", " << mine->reference.hi << "]";
        widths.push_back((mine->reference.hi - mine->reference.lo) / mine->depth.hi);
    }
    // Tight enough to judge: for 99% of the points the reference is known to within a quarter of the constant bias
    // (1e-3 of the depth), though interval arithmetic cannot see that s, t and the depth move together.
    std::sort(widths.begin(), widths.end());
    EXPECT_LT(widths[widths.size() * 99 / 100], 0.25e-3);
    std::printf("reference interval / depth: median %.3g, 99%% %.3g, max %.3g\n", widths[widths.size() / 2],
                widths[widths.size() * 99 / 100], widths.back());
}

using test_support::quad_mesh;

// A floor at y = 0 and a 1 x 1 square at height `height` above the origin, lit from (0, 4, 0).
Scene square_over_floor(float height) {
    Scene scene;
    scene.settings.shading = ShadingMode::blinn_phong;
    scene.settings.shadows.resolution = 256;
    scene.lights.push_back({{0, 4, 0}, glm::vec3(1.0f), 1.0f, false, true});
    scene.meshes.push_back(quad_mesh({-5, 0, -5}, {-5, 0, 5}, {5, 0, 5}, {5, 0, -5}));
    scene.meshes.push_back(quad_mesh({-0.5f, height, -0.5f}, {-0.5f, height, 0.5f}, {0.5f, height, 0.5f}, {0.5f, height, -0.5f}));
    return scene;
}

// The barycentrics of a floor point on the floor's triangle 0 or 1 (the diagonal from (-5, -5) to (5, 5)).
std::pair<uint32_t, glm::dvec3> floor_point(double x, double z) {
    const glm::dvec3 p(x, 0.0, z);
    const glm::dvec3 a(-5, 0, -5), b(-5, 0, 5), c(5, 0, 5), d(5, 0, -5);
    auto bary = [&](const glm::dvec3& u, const glm::dvec3& v, const glm::dvec3& w) {
        const double area = glm::cross(v - u, w - u).y;
        return glm::dvec3(glm::cross(v - p, w - p).y / area, glm::cross(w - p, u - p).y / area,
                          glm::cross(u - p, v - p).y / area);
    };
    const glm::dvec3 first = bary(a, b, c);
    if (first.x >= 0 && first.y >= 0 && first.z >= 0) return {0u, first};
    return {1u, bary(a, c, d)};
}

struct Sweep {
    int lit = 0, shadowed = 0, open = 0, inconsistent = 0;
    double open_from = 1e9, open_to = -1e9;  // the x range of open verdicts
};

// Sweeps floor points along z = 0.1 from x = 0 to 1.5, across the shadow's edge at x = 0.5 * 4 / (4 - h).
Sweep sweep(const Scene& scene) {
    const OracleScene geometry = oracle_scene(scene);
    const ShadowOracle oracle(scene, geometry, 2);
    const TransformedScene transformed = run_vertex_stage(scene, vertex_stage_needs(scene.settings.shading));
    const ShadowMaps maps = render_shadow_maps(scene, transformed.world_position, raster_backend(RasterPath::tiled), 2);
    Sweep out;
    for (double x = 0.0; x <= 1.5; x += 1.0 / 512) {
        const auto [id, bary] = floor_point(x, 0.1);
        const LightVisibility v = oracle.visibility(0, id, Interval3(bary));
        const float raster = maps.visibility(0, glm::vec3(float(x), 0.0f, 0.1f), glm::vec3(0, 1, 0));
        EXPECT_TRUE(v.allowed.contains(raster)) << "x " << x << ": raster " << raster << ", " << to_string(v.verdict);
        switch (v.verdict) {
            case ShadowVerdict::lit: ++out.lit; break;
            case ShadowVerdict::shadowed: ++out.shadowed; break;
            case ShadowVerdict::inconsistent: ++out.inconsistent; break;
            default:
                ++out.open;
                out.open_from = std::min(out.open_from, x);
                out.open_to = std::max(out.open_to, x);
        }
    }
    return out;
}

TEST(ShadowOracle, leavesOpenOnlyTheBandTheMapsFootprintMakesAcrossAShadowsEdge) {
    for (int pcf : {1, 3, 5}) {
        Scene scene = square_over_floor(1.0f);
        scene.settings.shadows.pcf = pcf;
        const Sweep s = sweep(scene);
        EXPECT_EQ(s.inconsistent, 0);
        EXPECT_GT(s.shadowed, 100);
        EXPECT_GT(s.lit, 100);
        // The edge is at x = 2/3. Where the taps and the ray agree the verdict is certain even with the edge in the
        // footprint, so the open band is where they may not: within the filter's reach and a texel of the edge (a
        // texel of the map is 2 * 4 / 256 of the floor directly below the light, about that at the edge).
        const double texel = 2.0 * 4.0 / 256.0, edge = 2.0 / 3.0, reach = (pcf / 2.0 + 1.0) * texel;
        EXPECT_GT(s.open, 0) << "pcf " << pcf;
        EXPECT_GT(s.open_from, edge - reach) << "pcf " << pcf;
        EXPECT_LT(s.open_to, edge + reach) << "pcf " << pcf;
    }
}

TEST(ShadowOracle, excusesAnOccluderWithinTheBiasAsDepthAndNoFurther) {
    // The square 2e-4 above the floor: within the constant bias (1e-3 of the depth 4), the map misses it; the ray
    // does not. Well above the floor it must shadow.
    const Sweep close = sweep(square_over_floor(2e-4f));
    EXPECT_EQ(close.inconsistent, 0);
    EXPECT_EQ(close.shadowed, 0);
    EXPECT_GT(close.open, 100);
    const Sweep above = sweep(square_over_floor(0.3f));
    EXPECT_EQ(above.inconsistent, 0);
    EXPECT_GT(above.shadowed, 100);
}

TEST(BoundaryEdges, areTheSilhouettesAndOpenEdgesSeenFromTheLight) {
    // A closed cube seen from a light above and to the side: no edge of a face pair that both face the light (or
    // both face away) is a boundary; every edge between a lit and an unlit face is.
    Scene scene;
    SceneMesh cube;
    mutable_data(cube).positions = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1}, {-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}};
    const int faces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {2, 3, 7, 6}, {1, 2, 6, 5}, {0, 4, 7, 3}};
    for (const auto& f : faces) {
        mutable_data(cube).triangles.push_back({{uint32_t(f[0]), uint32_t(f[1]), uint32_t(f[2])}});
        mutable_data(cube).triangles.push_back({{uint32_t(f[0]), uint32_t(f[2]), uint32_t(f[3])}});
    }
    scene.meshes.push_back(cube);
    scene.settings.shading = ShadingMode::blinn_phong;
    const OracleScene geometry = oracle_scene(scene);
    const std::vector<uint8_t> boundary = boundary_edges(scene, geometry, {0.5, 5.0, 0.3},
                                                          std::vector<uint8_t>(geometry.triangles.size(), 1));  // sees the top only
    int boundary_count = 0;
    for (uint8_t bits : boundary) boundary_count += __builtin_popcount(bits);
    // The light sees the top face (y = +1) alone: its 4 outer edges are the silhouette, counted once in the top
    // face's triangles and once in the side faces' triangles that share them.
    EXPECT_EQ(boundary_count, 8);
    for (uint32_t t : {6u, 7u}) EXPECT_NE(boundary[t], 0);  // the top face's triangles (face index 3: y = +1)
    for (uint32_t t : {4u, 5u}) EXPECT_EQ(boundary[t], 0);  // the bottom face: all its edges between unlit faces
}

}  // namespace
}  // namespace raster::oracle
