// Texture lookups: the analytic barycentric derivative against central differences of the barycentrics themselves,
// and the footprint step (a pixel; 1/sqrt(N) of one under N-sample SSAA; a pixel under MSAA).
#include "raster/shading/texture_lookup.h"

#include <cmath>
#include <memory>

#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>
#include <gtest/gtest.h>

#include "raster/texture/texture.h"

namespace raster {
namespace {

// The perspective-correct barycentrics of screen point p for clip-space vertices c: the weights b, summing to 1,
// whose clip-space combination projects to p (solved directly, in double).
glm::dvec3 barycentrics_at(const glm::vec4 c[3], int width, int height, glm::dvec2 p) {
    // sum_i b_i (x_i, y_i, w_i) = s (ndc_x, ndc_y, 1) for some s: a 3x3 system, then normalised.
    const double ndc_x = 2.0 * p.x / width - 1.0, ndc_y = 1.0 - 2.0 * p.y / height;
    const glm::dmat3 m(glm::dvec3(c[0].x, c[0].y, c[0].w), glm::dvec3(c[1].x, c[1].y, c[1].w),
                       glm::dvec3(c[2].x, c[2].y, c[2].w));
    const glm::dvec3 b = glm::inverse(m) * glm::dvec3(ndc_x, ndc_y, 1.0);
    return b / (b.x + b.y + b.z);
}

TEST(BarycentricGradient, matchesCentralDifferencesOfTheBarycentrics) {
    const int width = 320, height = 200;
    const glm::vec4 clip[3] = {{-0.8f, -0.5f, 0.9f, 1.5f}, {2.5f, -1.0f, 0.97f, 6.0f}, {0.2f, 3.0f, 0.99f, 9.0f}};
    const BarycentricGradient g = barycentric_gradient(clip[0], clip[1], clip[2], width, height);
    for (const glm::dvec2 p : {glm::dvec2(100.5, 80.5), glm::dvec2(180.25, 60.75), glm::dvec2(140.0, 120.0)}) {
        const glm::dvec3 b = barycentrics_at(clip, width, height, p);
        const double w = b.x * clip[0].w + b.y * clip[1].w + b.z * clip[2].w;
        const glm::dvec3 cx(g.column_x), cy(g.column_y);
        const glm::dvec3 analytic_x = w * (cx - b * (cx.x + cx.y + cx.z));
        const glm::dvec3 analytic_y = w * (cy - b * (cy.x + cy.y + cy.z));
        const double h = 1e-3;
        const glm::dvec3 fx = (barycentrics_at(clip, width, height, p + glm::dvec2(h, 0)) -
                               barycentrics_at(clip, width, height, p - glm::dvec2(h, 0))) / (2 * h);
        const glm::dvec3 fy = (barycentrics_at(clip, width, height, p + glm::dvec2(0, h)) -
                               barycentrics_at(clip, width, height, p - glm::dvec2(0, h))) / (2 * h);
        for (int i = 0; i < 3; ++i) {
            EXPECT_NEAR(analytic_x[i], fx[i], 1e-5 * std::fabs(fx[i]) + 1e-9) << i;
            EXPECT_NEAR(analytic_y[i], fy[i], 1e-5 * std::fabs(fy[i]) + 1e-9) << i;
        }
    }
}

Scene textured_triangle(int samples, bool msaa) {
    Scene scene;
    scene.settings.samples = samples;
    scene.settings.msaa = msaa;
    scene.settings.shading = ShadingMode::unlit;
    SceneMesh mesh;
    mutable_data(mesh).positions = {{-1, -1, 0}, {1, -1, -1}, {0, 1, -2}};
    mutable_data(mesh).triangles = {{{0, 1, 2}}};
    mutable_data(mesh).corner_uvs = {{{glm::vec2(0, 0), glm::vec2(3, 0), glm::vec2(0, 2)}}};
    TextureBinding binding;
    binding.texture = std::make_shared<Texture>();
    mesh.material.texture = binding;
    scene.meshes.push_back(mesh);
    return scene;
}

TEST(TextureLookup, theFootprintIsASamplesShareOfThePixelUnderSsaaAndThePixelUnderMsaa) {
    auto derivative = [](int samples, bool msaa) {
        const Scene scene = textured_triangle(samples, msaa);
        const TransformedScene geometry = run_vertex_stage(scene, vertex_stage_needs(scene.settings.shading));
        return TextureLookup(scene, geometry).at(0, glm::vec3(0.3f, 0.3f, 0.4f)).duv_dx;
    };
    const glm::vec2 one = derivative(1, false);
    ASSERT_GT(std::fabs(one.x) + std::fabs(one.y), 0.0f);
    const glm::vec2 sixteen = derivative(16, false), msaa = derivative(16, true), four = derivative(4, false);
    for (int k = 0; k < 2; ++k) {
        EXPECT_NEAR(sixteen[k], one[k] / 4.0f, 1e-6f * std::fabs(one[k]));
        EXPECT_NEAR(four[k], one[k] / 2.0f, 1e-6f * std::fabs(one[k]));
        EXPECT_EQ(msaa[k], one[k]);
    }
}

}  // namespace
}  // namespace raster
