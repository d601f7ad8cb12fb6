// The resolve: each pixel's bytes are the weighted mean of its shaded samples (SSAA, MSAA, alpha), computed here
// from Shader::shade one point at a time, and do not depend on the other pixels shaded in the same batch.
#include "raster/resolve/resolve.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "raster/geometry/vertex_stage.h"
#include "tests/support/quad_meshes.h"

namespace raster {
namespace {

using test_support::quad_mesh;

// Two lit quads at an angle to each other (four triangles of different colours and normals).
Scene lit_scene() {
    Scene scene;
    scene.settings.shading = ShadingMode::blinn_phong;
    scene.lights.push_back({glm::vec3(2, 3, 4), glm::vec3(1.0f), 1.0f, false, false});
    scene.meshes.push_back(quad_mesh({-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}));
    scene.meshes.push_back(quad_mesh({-1, -1, 0}, {-1, 1, 0}, {-1, 1, 2}, {-1, -1, 2}));
    scene.meshes[0].material.color = glm::vec3(0.8f, 0.3f, 0.2f);
    scene.meshes[1].material.color = glm::vec3(0.2f, 0.5f, 0.9f);
    return scene;
}

// Pixels of `samples` samples each, in one array: each sample empty or on one of the four triangles, at random
// barycentrics; about a third of the pixels show one triangle in every sample, a tenth none.
struct Pixels {
    std::vector<uint32_t> triangle;
    std::vector<glm::vec3> bary;
};
Pixels random_pixels(int count, int samples, std::mt19937& rng) {
    Pixels p;
    std::uniform_int_distribution<int> kind(0, 9), tri(0, 4);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    for (int i = 0; i < count; ++i) {
        const int k = kind(rng);
        const uint32_t one = static_cast<uint32_t>(tri(rng) % 4);
        for (int s = 0; s < samples; ++s) {
            const int t = tri(rng);
            p.triangle.push_back(k == 0 ? kNoTriangle : k <= 3 ? one : t == 4 ? kNoTriangle : static_cast<uint32_t>(t));
            const float u = unit(rng), v = unit(rng) * (1.0f - u);
            p.bary.emplace_back(u, v, 1.0f - u - v);
        }
    }
    return p;
}

// The pixel's colour (and alpha) by the resolve's written rule, in double: SSAA shades every covered sample, MSAA
// each triangle once at its first sample for all its samples, a one-triangle pixel under MSAA or one sample is its
// shade; uncovered samples take the background unless alpha, which averages the covered ones only.
std::vector<double> expected_pixel(const Shader& shader, const ResolveParams& params, int samples,
                                   const uint32_t* triangle, const glm::vec3* bary) {
    glm::dvec3 sum(0.0);
    int covered = 0;
    for (int s = 0; s < samples; ++s) {
        if (triangle[s] == kNoTriangle) continue;
        ++covered;
        int first = s;  // MSAA: the triangle's first sample
        if (params.msaa)
            for (int earlier = s - 1; earlier >= 0; --earlier)
                if (triangle[earlier] == triangle[s]) first = earlier;
        sum += glm::dvec3(shader.shade(triangle[first], bary[first]));
    }
    glm::dvec3 color(params.background);
    if (covered > 0)
        color = params.alpha ? sum / double(covered)
                             : (sum + double(samples - covered) * glm::dvec3(params.background)) / double(samples);
    std::vector<double> out = {color.x, color.y, color.z};
    if (params.alpha) out.push_back(double(covered) / samples);
    return out;
}

// The points the resolve's two queues get, by the written rule: a pixel one triangle covers is one point under
// MSAA or one sample; any other covered pixel gives a point per covered sample (SSAA) or per triangle (MSAA).
struct QueuedPoints {
    size_t one_triangle = 0, other = 0;
};
QueuedPoints queued_points(const Pixels& pixels, int samples, bool msaa) {
    QueuedPoints q;
    for (size_t first = 0; first < pixels.triangle.size(); first += static_cast<size_t>(samples)) {
        std::vector<uint32_t> seen;
        size_t covered = 0;
        for (int s = 0; s < samples; ++s) {
            const uint32_t t = pixels.triangle[first + static_cast<size_t>(s)];
            if (t == kNoTriangle) continue;
            ++covered;
            if (std::find(seen.begin(), seen.end(), t) == seen.end()) seen.push_back(t);
        }
        if (seen.size() == 1 && covered == static_cast<size_t>(samples) && (msaa || samples == 1)) ++q.one_triangle;
        else if (covered > 0) q.other += msaa ? seen.size() : covered;
    }
    return q;
}

double to_unit_byte(double v) { return v <= 0.0 ? 0.0 : v >= 1.0 ? 255.0 : std::floor(v * 255.0 + 0.5); }

struct Case {
    int samples;
    bool msaa, alpha;
};

TEST(PixelResolver, givesEachPixelTheWeightedMeanOfItsShadedSamplesWhateverElseIsInItsBatch) {
    const Scene scene = lit_scene();
    const TransformedScene geometry = run_vertex_stage(scene, vertex_stage_needs(scene.settings.shading));
    const Shader shader(scene, geometry);
    std::mt19937 rng(7);
    for (const Case c : {Case{1, false, false}, Case{4, false, false}, Case{4, true, false}, Case{16, true, false},
                         Case{8, false, true}, Case{4, true, true}}) {
        SCOPED_TRACE(testing::Message() << c.samples << " samples" << (c.msaa ? " MSAA" : "") << (c.alpha ? " alpha" : ""));
        ResolveParams params;
        params.msaa = c.msaa;
        params.alpha = c.alpha;
        params.background = glm::vec3(0.1f, 0.2f, 0.3f);
        const PixelResolver resolver(shader, params, c.samples);
        const int count = 8000, channels = resolver.channels();
        const Pixels pixels = random_pixels(count, c.samples, rng);
        // All the pixels through one batch, and each pixel alone.
        std::vector<uint8_t> together(static_cast<size_t>(count) * channels), alone(together.size());
        ResolveBatch batch;
        for (int i = 0; i < count; ++i) {
            const size_t first = static_cast<size_t>(i) * c.samples;
            resolver.add(&pixels.triangle[first], &pixels.bary[first], &together[static_cast<size_t>(i) * channels],
                         batch);
            ResolveBatch single;
            resolver.add(&pixels.triangle[first], &pixels.bary[first], &alone[static_cast<size_t>(i) * channels],
                         single);
            resolver.finish(single);
        }
        resolver.finish(batch);
        // Each queue the case uses took more than two batches' worth of points, so it was shaded part-way.
        const QueuedPoints queued = queued_points(pixels, c.samples, c.msaa);
        if (c.msaa || c.samples == 1) {
            ASSERT_GT(queued.one_triangle, 2 * PixelResolver::kBatchPoints);
        }
        if (c.samples > 1) {
            ASSERT_GT(queued.other, 2 * PixelResolver::kBatchPoints);
        }
        EXPECT_EQ(together, alone);
        // Against the rule: the float sums may round a value across a half, so one step either way.
        int exact = 0;
        for (int i = 0; i < count; ++i) {
            const size_t first = static_cast<size_t>(i) * c.samples;
            const std::vector<double> want =
                expected_pixel(shader, params, c.samples, &pixels.triangle[first], &pixels.bary[first]);
            for (int ch = 0; ch < channels; ++ch) {
                const double got = together[static_cast<size_t>(i) * channels + ch];
                ASSERT_LE(std::abs(got - to_unit_byte(want[ch])), 1.0) << "pixel " << i << " channel " << ch;
                exact += got == to_unit_byte(want[ch]);
            }
        }
        EXPECT_GT(exact, count * channels * 95 / 100);
    }
}

}  // namespace
}  // namespace raster
