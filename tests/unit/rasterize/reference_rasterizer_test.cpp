// Coverage: the rasterizer's covered samples equal an independent exact-integer computation on the snapped
// vertices, the top-left rule covers shared edges and vertices exactly once, and depth keeps the nearest.
#include "raster/rasterize/per_sample.h"
#include "raster/rasterize/reference_rasterizer.h"

#include <cstdint>
#include <random>

#include <gtest/gtest.h>

#include "raster/geometry/sample_pattern.h"
#include "raster/geometry/setup.h"
#include "properties/reference/coverage_reference.h"

namespace raster {
namespace {

constexpr int kSize = 32;  // a power of two, so screen positions on the 1/256 grid are exact in NDC floats

// A polygon at view depth `w` whose vertices land exactly on the given screen positions (pixels, y down).
ClippedPolygon screen_polygon(std::initializer_list<glm::dvec2> points, float w = 1.0f, float depth = 0.5f) {
    ClippedPolygon polygon;
    for (const glm::dvec2& p : points) {
        const float x = static_cast<float>(2.0 * p.x / kSize - 1.0), y = static_cast<float>(1.0 - 2.0 * p.y / kSize);
        polygon.vertices[polygon.count] = {glm::vec4(x * w, y * w, depth * w, w), glm::vec3(0)};
        polygon.vertices[polygon.count].bary[polygon.count % 3] = 1.0f;
        ++polygon.count;
    }
    return polygon;
}

std::vector<TriangleSetup> set_up(const std::vector<ClippedPolygon>& polygons, int snap_bits = 8) {
    std::vector<TriangleSetup> setups;
    const FrameParams params = frame_params(kSize, kSize, snap_bits);
    for (size_t i = 0; i < polygons.size(); ++i) setup_polygon(polygons[i], static_cast<uint32_t>(i), params, setups);
    return setups;
}

VisibilityBuffer run(const std::vector<TriangleSetup>& setups, int samples, SamplePattern pattern, int snap_bits = 8,
                     int threads = 1) {
    FrameParams params = frame_params(kSize, kSize, snap_bits, sample_offsets(samples, pattern));
    params.threads = threads;
    VisibilityBuffer visibility;
    rasterize_reference(setups, params, visibility);
    return visibility;
}

// The independent reference: exact orientation tests in 128-bit integers on the snapped vertices.
using reference::owns_edge;
using reference::Point;
using reference::reference_covers;
using reference::snap_to_grid;

TEST(Rasterize, ownsEdgeReferenceAgreesWithTheDefinition) {
    // The reference's own sanity: in the triangle (0,0) (4,0) (0,4) (y down), the top edge is y = 0 and the left
    // edge is x = 0; the hypotenuse is neither.
    const Point a{0, 0}, b{4, 0}, c{0, 4};
    EXPECT_TRUE(owns_edge(a, b, c));   // top
    EXPECT_TRUE(owns_edge(c, a, b));   // left
    EXPECT_FALSE(owns_edge(b, c, a));  // hypotenuse: bottom-right
    EXPECT_TRUE(reference_covers(a, b, c, {1, 0}));
    EXPECT_TRUE(reference_covers(a, b, c, {0, 1}));
    EXPECT_FALSE(reference_covers(a, b, c, {2, 2}));
}

TEST(Rasterize, coveredSamplesEqualExactIntegerReference) {
    std::mt19937 random(12345);
    std::uniform_real_distribution<double> coordinate(-4.0, kSize + 4.0);
    struct Mode {
        int samples;
        SamplePattern pattern;
        int snap_bits;
    };
    const Mode modes[] = {{1, SamplePattern::standard, 8}, {4, SamplePattern::standard, 8},
                          {16, SamplePattern::standard, 4}, {9, SamplePattern::grid, 8},
                          {4, SamplePattern::standard, 2},  {16, SamplePattern::grid, 12}};
    int compared = 0, covered = 0;
    for (const Mode& mode : modes) {
        const int fixed_bits = fixed_bits_for(mode.snap_bits);
        const FixedSampleOffsets offsets = fixed_sample_offsets(sample_offsets(mode.samples, mode.pattern), fixed_bits);
        for (int trial = 0; trial < 60; ++trial) {
            // Vertices on the snap grid, some outside the viewport (kept inside the clip volume by clamping below).
            glm::dvec2 p[3];
            for (auto& v : p) {
                v = {std::clamp(coordinate(random), 0.0, double(kSize)), std::clamp(coordinate(random), 0.0, double(kSize))};
                const double grid = std::ldexp(1.0, mode.snap_bits);
                v = glm::round(v * grid) / grid;
            }
            if (trial % 5 == 0) p[2].y = p[1].y;  // horizontal edges exercise the top rule
            if (trial % 7 == 0) p[2].x = p[0].x;  // vertical edges exercise the left rule
            const auto setups = set_up({screen_polygon({p[0], p[1], p[2]})}, mode.snap_bits);
            const VisibilityBuffer visibility = run(setups, mode.samples, mode.pattern, mode.snap_bits);
            Point v[3];
            for (int i = 0; i < 3; ++i)
                v[i] = {snap_to_grid(p[i].x, mode.snap_bits, fixed_bits), snap_to_grid(p[i].y, mode.snap_bits, fixed_bits)};
            for (int y = 0; y < kSize; ++y)
                for (int x = 0; x < kSize; ++x)
                    for (int s = 0; s < mode.samples; ++s) {
                        const Point sample{(int64_t{x} << fixed_bits) + offsets.x[s], (int64_t{y} << fixed_bits) + offsets.y[s]};
                        const bool expected = reference_covers(v[0], v[1], v[2], sample);
                        const bool actual = visibility.triangle[visibility.index(x, y, s)] != kNoTriangle;
                        ASSERT_EQ(actual, expected) << "trial " << trial << " samples " << mode.samples << " pixel (" << x
                                                    << ", " << y << ") sample " << s;
                        ++compared;
                        covered += expected;
                    }
        }
    }
    EXPECT_GT(covered, compared / 20);  // the trials really covered something
}

// Sums, over several triangles rasterized separately, how many cover each sample.
std::vector<int> coverage_counts(const std::vector<ClippedPolygon>& polygons, int samples, SamplePattern pattern) {
    std::vector<int> counts;
    for (const ClippedPolygon& polygon : polygons) {
        const VisibilityBuffer visibility = run(set_up({polygon}), samples, pattern);
        counts.resize(visibility.size(), 0);
        for (size_t i = 0; i < visibility.size(); ++i) counts[i] += visibility.triangle[i] != kNoTriangle;
    }
    return counts;
}

TEST(Rasterize, sharedEdgeSamplesAreCoveredExactlyOnce) {
    // A square split along both diagonals into four triangles around its centre; the centre, the diagonals and
    // the square's midlines pass exactly through pixel centres (1 sample) and grid samples.
    const glm::dvec2 a{4.5, 4.5}, b{20.5, 4.5}, c{20.5, 20.5}, d{4.5, 20.5}, centre{12.5, 12.5};
    const std::vector<ClippedPolygon> fan = {screen_polygon({a, b, centre}), screen_polygon({b, c, centre}),
                                             screen_polygon({c, d, centre}), screen_polygon({d, a, centre})};
    for (int samples : {1, 16}) {
        const auto counts = coverage_counts(fan, samples, samples == 1 ? SamplePattern::standard : SamplePattern::grid);
        int inside = 0;
        for (int y = 5; y < 20; ++y)
            for (int x = 5; x < 20; ++x)
                for (int s = 0; s < samples; ++s) {
                    ASSERT_EQ(counts[(static_cast<size_t>(y) * kSize + x) * samples + s], 1)
                        << "pixel (" << x << ", " << y << ") sample " << s;
                    ++inside;
                }
        EXPECT_GT(inside, 0);
    }
}

TEST(Rasterize, sharedVertexOnASampleIsCoveredExactlyOnce) {
    // Eight triangles around a vertex exactly at pixel (10, 10)'s centre, in both windings.
    const glm::dvec2 centre{10.5, 10.5};
    std::vector<ClippedPolygon> fan;
    const glm::dvec2 ring[8] = {{14.5, 10.5}, {13.5, 13.5}, {10.5, 14.5}, {7.5, 13.5},
                                {6.5, 10.5},  {7.5, 7.5},   {10.5, 6.5},  {13.5, 7.5}};
    for (int i = 0; i < 8; ++i) {
        if (i % 2) fan.push_back(screen_polygon({centre, ring[i], ring[(i + 1) % 8]}));
        else fan.push_back(screen_polygon({ring[(i + 1) % 8], ring[i], centre}));
    }
    const auto counts = coverage_counts(fan, 1, SamplePattern::standard);
    EXPECT_EQ(counts[10 * kSize + 10], 1);
    EXPECT_EQ(counts[10 * kSize + 12], 1);  // on the shared edge towards ring[0]
}

TEST(Rasterize, subPixelTriangleIsNotDiscarded) {
    // A triangle of area 1/32 px^2 around pixel (3, 3)'s centre still covers that sample.
    const auto setups = set_up({screen_polygon({{3.375, 3.375}, {3.625, 3.375}, {3.5, 3.625}})});
    ASSERT_EQ(setups.size(), 1u);
    const VisibilityBuffer visibility = run(setups, 1, SamplePattern::standard);
    EXPECT_EQ(visibility.triangle[visibility.index(3, 3, 0)], 0u);
}

TEST(Rasterize, nearestSurfaceWinsWhateverTheDrawOrder) {
    // The same square at view depth 2 and 5: the one at depth 2 is visible whichever is drawn first.
    for (bool near_first : {true, false}) {
        std::vector<ClippedPolygon> quads = {screen_polygon({{2, 2}, {30, 2}, {30, 30}, {2, 30}}, 2.0f, 0.9f),
                                             screen_polygon({{2, 2}, {30, 2}, {30, 30}, {2, 30}}, 5.0f, 0.2f)};
        if (!near_first) std::swap(quads[0], quads[1]);
        const VisibilityBuffer visibility = run(set_up(quads), 1, SamplePattern::standard);
        const size_t at = visibility.index(16, 16, 0);
        EXPECT_NEAR(visibility.view_depth[at], 2.0f, 1e-5f);
        EXPECT_EQ(visibility.triangle[at], near_first ? 0u : 1u);
    }
}

TEST(Rasterize, perspectiveCorrectBarycentricsFollowOneOverW) {
    // Edge from a vertex at w = 1 to one at w = 3: at the screen midpoint the perspective-correct weight of the
    // far vertex is (1/2 * 1/3) / (1/2 * 1 + 1/2 * 1/3) = 1/4, not the affine 1/2.
    ClippedPolygon polygon = screen_polygon({{0, 8}, {32, 8}, {0, 32}});
    polygon.vertices[1].position *= 3.0f;  // same screen position, w = 3
    const VisibilityBuffer visibility = run(set_up({polygon}), 1, SamplePattern::standard);
    // Pixel (15, 8) centre is at screen (15.5, 8.5); barycentrics on the line y = 8 + 0.5.
    const size_t at = visibility.index(15, 8, 0);
    ASSERT_EQ(visibility.triangle[at], 0u);
    // Screen barycentrics there: l1 = 15.5/32, l2 = 0.5/24 (from the edge to the third vertex), l0 = rest.
    const double l1 = 15.5 / 32.0, l2 = 0.5 / 24.0, l0 = 1.0 - l1 - l2;
    const double m0 = l0, m1 = l1 / 3.0, m2 = l2, total = m0 + m1 + m2;
    EXPECT_NEAR(visibility.bary[at].y, m1 / total, 1e-5);
    EXPECT_NEAR(visibility.view_depth[at], 1.0 / total, 1e-4);
    EXPECT_NEAR(visibility.bary[at].x + visibility.bary[at].y + visibility.bary[at].z, 1.0f, 1e-6f);
}

TEST(Rasterize, resultDoesNotDependOnThreadCount) {
    std::vector<ClippedPolygon> polygons;
    std::mt19937 random(7);
    std::uniform_real_distribution<double> coordinate(0.0, kSize);
    std::uniform_real_distribution<float> depth(1.0f, 9.0f);
    for (int i = 0; i < 50; ++i)
        polygons.push_back(screen_polygon({{coordinate(random), coordinate(random)},
                                           {coordinate(random), coordinate(random)},
                                           {coordinate(random), coordinate(random)}},
                                          depth(random), 0.1f));
    const auto setups = set_up(polygons);
    const VisibilityBuffer one = run(setups, 4, SamplePattern::standard, 8, 1);
    const VisibilityBuffer three = run(setups, 4, SamplePattern::standard, 8, 3);
    EXPECT_EQ(one.triangle, three.triangle);
    EXPECT_EQ(one.view_depth, three.view_depth);
}

}  // namespace
}  // namespace raster
