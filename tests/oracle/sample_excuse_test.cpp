// The inspector's excuses: each names the figure the classifier measured and its bound, and the two sit on the side
// of each other that the class says (within or at the bound for agree and the ambiguous classes, past it for the
// genuine ones), at the bound's edge and over a sweep of perturbed samples on crossing triangles.
#include "oracle/compare/sample_excuse.h"

#include <random>

#include <gtest/gtest.h>

#include "tests/support/oracle_test_scenes.h"

namespace raster::oracle {
namespace {

using testing::camera_at_origin;
using testing::covered_by;
using testing::reference_for;
using testing::scene_with_triangles;

const SampleEntry kEmpty{};

// The excuse's figure is on the side of its bound that the class says.
void expect_consistent(const SampleExcuse& excuse, SampleClass klass, const std::string& where) {
    if (!excuse.has_figure) return;
    if (is_genuine(klass))
        EXPECT_GT(excuse.measured, excuse.bound) << where << ": " << to_string(klass) << ", " << excuse.rule;
    else
        EXPECT_LE(excuse.measured, excuse.bound) << where << ": " << to_string(klass) << ", " << excuse.rule;
}

TEST(SampleExcuse, anEdgeBandSampleGivesItsDistanceToTheEdgeAgainstTheBand) {
    const Scene scene = scene_with_triangles({{{{-1, -1, -3}, {-1, 1, -3}, {1, 0, -3}}}}, camera_at_origin(), 100, 100);
    const ReferenceGeometry reference = reference_for(scene);
    const double edge = reference.screen_vertices(0)[0].x, radius = reference.polygon(0).radius;
    const glm::dvec2 inside(edge - radius * 0.5, 50.0), outside(edge - radius * 2.0, 50.0);
    const SampleEntry at_inside = covered_by(0, reference, inside), at_outside = covered_by(0, reference, outside);
    const SampleClass in_band = classify_sample(reference, inside, at_inside, kEmpty);
    ASSERT_EQ(in_band, SampleClass::edge_band);
    const SampleExcuse band = sample_excuse(reference, inside, at_inside, kEmpty, in_band);
    EXPECT_NE(band.rule.find("triangle 0"), std::string::npos) << band.rule;
    ASSERT_TRUE(band.has_figure);
    EXPECT_NEAR(band.measured, radius * 0.5, radius * 1e-6);
    EXPECT_EQ(band.bound, radius);
    const SampleClass beyond = classify_sample(reference, outside, at_outside, kEmpty);
    ASSERT_EQ(beyond, SampleClass::visibility);
    const SampleExcuse none = sample_excuse(reference, outside, at_outside, kEmpty, beyond);
    ASSERT_TRUE(none.has_figure);
    EXPECT_NEAR(none.measured, radius * 2.0, radius * 1e-6);
    EXPECT_EQ(none.bound, radius);
}

TEST(SampleExcuse, aBarycentricGapIsGivenAgainstTheToleranceTheClassifierUsed) {
    const Scene scene = scene_with_triangles({{{{-1, -1, -2}, {1, -1, -3}, {0, 1, -6}}}}, camera_at_origin(), 100, 100);
    const ReferenceGeometry reference = reference_for(scene);
    const glm::dvec2 p(50.5, 50.5);
    const SampleEntry exact = covered_by(0, reference, p);
    const glm::dvec3 tolerance = agreement_tolerance(reference, 0, p).bary;
    for (const double factor : {0.5, 2.0}) {
        SampleEntry shifted = exact;
        shifted.bary.x += static_cast<float>(tolerance.x * factor);
        shifted.bary.y -= static_cast<float>(tolerance.x * factor);
        const SampleClass klass = classify_sample(reference, p, shifted, exact);
        EXPECT_EQ(klass, factor < 1 ? SampleClass::agree : SampleClass::barycentrics);
        const SampleExcuse excuse = sample_excuse(reference, p, shifted, exact, klass);
        EXPECT_NE(excuse.rule.find("barycentric"), std::string::npos) << excuse.rule;
        expect_consistent(excuse, klass, "factor " + std::to_string(factor));
    }
}

// Two triangles crossing each other and the near plane, sampled all over with both renderers' answers perturbed:
// every class the classifier gives comes with a figure on its side of the bound.
TEST(SampleExcuse, everyClassOnCrossingTrianglesHasItsFigureOnTheRightSideOfItsBound) {
    const Scene scene = scene_with_triangles(
        {{{{-2, -2, -4}, {2, -2, -2}, {0, 2, -6}}}, {{{-2, 1, -2}, {2, 1, -6}, {0, -2, -4}}},
         {{{-3, -1, 1}, {3, -1, 1}, {0, -1, -30}}}},
        camera_at_origin(60.0f, 0.5f, 50.0f), 64, 64);
    const ReferenceGeometry reference = reference_for(scene);
    std::mt19937 random(7);
    std::uniform_real_distribution<double> position(0.0, 64.0), unit(0.0, 1.0);
    std::array<int, kSampleClassCount> seen{};
    for (int n = 0; n < 20000; ++n) {
        const glm::dvec2 p(position(random), position(random));
        SampleEntry sides[2];
        for (SampleEntry& side : sides) {
            const int pick = static_cast<int>(unit(random) * 4);  // a triangle, or none
            if (pick == 3 || !reference.contains(static_cast<uint32_t>(pick), p)) {
                // A triangle that misses the sample, as a renderer off by a little or a lot may report it.
                side = pick == 3 ? kEmpty : SampleEntry{static_cast<uint32_t>(pick), glm::vec3(1 / 3.0f), 5.0f};
                continue;
            }
            side = covered_by(static_cast<uint32_t>(pick), reference, p);
            const float scale = static_cast<float>(std::pow(10.0, -7.0 + 6.0 * unit(random)));
            side.bary += glm::vec3(scale, -scale, 0.0f);
            side.view_depth *= 1.0f + scale;
        }
        const SampleClass klass = classify_sample(reference, p, sides[0], sides[1]);
        ++seen[static_cast<size_t>(klass)];
        const SampleExcuse excuse = sample_excuse(reference, p, sides[0], sides[1], klass);
        EXPECT_FALSE(excuse.rule.empty());
        expect_consistent(excuse, klass, "(" + std::to_string(p.x) + ", " + std::to_string(p.y) + ")");
    }
    // The sweep reaches the classes it is meant to explain.
    for (SampleClass klass : {SampleClass::agree, SampleClass::edge_band, SampleClass::clip_boundary,
                              SampleClass::visibility, SampleClass::barycentrics})
        EXPECT_GT(seen[static_cast<size_t>(klass)], 0) << to_string(klass);
}

}  // namespace
}  // namespace raster::oracle
