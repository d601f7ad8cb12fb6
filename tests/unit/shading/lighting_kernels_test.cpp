// The SIMD lighting kernels: the same bits on every Highway target the CPU runs and on the scalar fallback, batch
// position and run boundaries never changing a point's bits, and agreement with a double-precision reference.
#include "raster/shading/lighting_kernels.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "raster/shading/lighting.h"
#include "raster/simd/simd_targets.h"
#include "tests/support/pinned_simd_target.h"

namespace raster {
namespace {

struct Case {
    LightingBatch batch;  // inputs: position, normal (any length), visibility rows
    std::vector<float> visibility;
    std::vector<Light> lights;
    Material material;
};

// A batch of points drawn to reach every branch: zero normals, points on a light, lights behind the surface,
// shadowed (0), half-lit and lit lights, attenuated and plain lights, a directional light and a spot light whose
// cone holds some points, fades over others and misses the rest.
Case random_case(uint32_t seed, float exponent) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> coord(-3.0f, 3.0f), unit(0.0f, 1.0f);
    Case c;
    c.lights = {{{2, 3, 1}, {1, 0.9f, 0.8f}, 0.9f, false},
                {{-1, 0.5f, 2}, {0.5f, 0.6f, 0.9f}, 3.0f, true},
                {{0, -2, -2}, {0.2f, 1, 0.4f}, 0.5f, false}};
    Light sun;
    sun.type = LightType::directional;
    sun.direction = {-1.0f, -2.0f, -0.5f};
    sun.color = {1.0f, 0.95f, 0.8f};
    sun.intensity = 0.7f;
    Light spot;
    spot.type = LightType::spot;
    spot.position = {0.5f, 2.5f, 1.0f};
    spot.direction = {0.0f, -1.0f, -0.2f};
    spot.inner_cone = 0.35f;
    spot.outer_cone = 1.4f;
    spot.attenuate = true;
    spot.intensity = 2.0f;
    c.lights.push_back(sun);
    c.lights.push_back(spot);
    c.material.ambient = {0.1f, 0.12f, 0.08f};
    c.material.diffuse = {0.8f, 0.3f, 0.25f};
    c.material.specular = {0.5f, 0.5f, 0.6f};
    c.material.exponent = exponent;
    c.visibility.assign(c.lights.size() * LightingBatch::kRow, 1.0f);
    for (size_t j = 0; j < kLightingBatch; ++j) {
        for (int k = 0; k < 3; ++k) {
            c.batch.position[k][j] = coord(rng);
            c.batch.normal[k][j] = coord(rng);
        }
        if (j % 13 == 5)
            for (int k = 0; k < 3; ++k) c.batch.normal[k][j] = 0.0f;  // degenerate normal
        if (j % 17 == 3)
            for (int k = 0; k < 3; ++k) c.batch.position[k][j] = c.lights[0].position[k];  // on the light
        for (size_t l = 0; l < c.lights.size(); ++l) {
            const float u = unit(rng);
            c.visibility[l * LightingBatch::kRow + j] = u < 0.2f ? 0.0f : u < 0.4f ? 0.5f : 1.0f;
        }
    }
    return c;
}

// The kernels over the case in the runs [0, 7), [7, 40), [40, 64), so runs start off vector boundaries.
LightingBatch lit(const Case& c, SpecularModel model, bool with_visibility) {
    LightingBatch batch = c.batch;
    orient_points(batch, kLightingBatch, Viewer{glm::vec3(0.5f, 4.0f, 6.0f)});
    const size_t cuts[] = {0, 7, 40, kLightingBatch};
    for (int r = 0; r < 3; ++r)
        light_points(batch, cuts[r], cuts[r + 1] - cuts[r], c.material, c.lights, glm::vec3(0.3f), model,
                     with_visibility ? c.visibility.data() : nullptr);
    return batch;
}

bool same_bits(const LightingBatch& a, const LightingBatch& b, std::string& where) {
    for (int k = 0; k < 3; ++k)
        for (size_t j = 0; j < kLightingBatch; ++j) {
            const float pairs[4][2] = {{a.normal[k][j], b.normal[k][j]}, {a.to_eye[k][j], b.to_eye[k][j]},
                                       {a.diffuse[k][j], b.diffuse[k][j]}, {a.specular[k][j], b.specular[k][j]}};
            for (const auto& pair : pairs)
                if (std::memcmp(&pair[0], &pair[1], sizeof(float)) != 0) {
                    std::ostringstream text;
                    text << "point " << j << " row " << k << ": " << std::hexfloat << pair[0] << " vs " << pair[1];
                    where = text.str();
                    return false;
                }
        }
    return true;
}

TEST(LightingKernels, everyTargetTheCpuRunsGivesTheScalarFallbacksBits) {
    const std::vector<int64_t> targets = simd_targets();
    ASSERT_GE(targets.size(), 1u);
    const std::string fallback = simd_target_name(targets.back());
    EXPECT_TRUE(fallback == "EMU128" || fallback == "SCALAR") << "the last target is " << fallback;
    std::printf("lighting targets this CPU runs:");
    for (const int64_t target : targets) std::printf(" %s", simd_target_name(target).c_str());
    std::printf("\n");
    for (const float exponent : {40.0f, 0.0f, 2.5f, 300.0f})
        for (const SpecularModel model : {SpecularModel::blinn, SpecularModel::phong})
            for (const bool with_visibility : {false, true}) {
                const Case c = random_case(static_cast<uint32_t>(exponent * 7) + 1, exponent);
                LightingBatch expected;
                {
                    const test_support::PinnedSimdTarget fallback_only(targets.back());
                    expected = lit(c, model, with_visibility);
                }
                for (const int64_t target : targets) {
                    const test_support::PinnedSimdTarget pinned(target);
                    std::string where;
                    EXPECT_TRUE(same_bits(lit(c, model, with_visibility), expected, where))
                        << simd_target_name(target) << " differs from " << fallback << " at " << where
                        << " (exponent " << exponent << ", model " << int(model) << ")";
                }
            }
}

TEST(LightingKernels, aPointGetsTheSameBitsAloneAsInABatch) {
    // evaluate_lighting lights one point in lane 0; the batch put it in lane j of a run.
    const Case c = random_case(7, 40.0f);
    const LightingBatch batch = lit(c, SpecularModel::blinn, true);
    for (size_t j = 0; j < kLightingBatch; ++j) {
        std::vector<float> visibility(c.lights.size());
        for (size_t l = 0; l < c.lights.size(); ++l) visibility[l] = c.visibility[l * LightingBatch::kRow + j];
        const glm::vec3 position(c.batch.position[0][j], c.batch.position[1][j], c.batch.position[2][j]);
        const glm::vec3 normal(batch.normal[0][j], batch.normal[1][j], batch.normal[2][j]);
        const glm::vec3 to_eye(batch.to_eye[0][j], batch.to_eye[1][j], batch.to_eye[2][j]);
        const LightingTerms one = evaluate_lighting(position, normal, to_eye, c.material, c.lights, glm::vec3(0.3f),
                                                    SpecularModel::blinn, visibility.data());
        for (int k = 0; k < 3; ++k) {
            EXPECT_EQ(one.diffuse[k], batch.diffuse[k][j]) << "point " << j;
            EXPECT_EQ(one.specular[k], batch.specular[k][j]) << "point " << j;
        }
    }
}

// Blinn-Phong in double precision, written from the formula (docs/scene-format.md "Shading"), not from the kernel.
glm::dvec3 reference_term(const Case& c, size_t j, bool diffuse_term) {
    const glm::dvec3 p(c.batch.position[0][j], c.batch.position[1][j], c.batch.position[2][j]);
    glm::dvec3 n(c.batch.normal[0][j], c.batch.normal[1][j], c.batch.normal[2][j]);
    n = glm::length(n) > 0 ? n / glm::length(n) : glm::dvec3(0);
    const glm::dvec3 v = glm::normalize(glm::dvec3(0.5, 4.0, 6.0) - p);
    glm::dvec3 sum = diffuse_term ? glm::dvec3(c.material.ambient) * 0.3 : glm::dvec3(0);
    for (size_t l = 0; l < c.lights.size(); ++l) {
        const Light& light = c.lights[l];
        const double visible = c.visibility[l * LightingBatch::kRow + j];
        // docs/scene-format.md "Lights": a directional light along -direction, unattenuated; a spot light faded.
        const bool directional = light.type == LightType::directional;
        const glm::dvec3 to_light = directional ? -glm::dvec3(light.direction) : glm::dvec3(light.position) - p;
        const double r2 = glm::dot(to_light, to_light);
        if (r2 <= 0 || visible == 0) continue;
        const glm::dvec3 l_unit = to_light / std::sqrt(r2);
        const double n_dot_l = glm::dot(n, l_unit);
        if (n_dot_l <= 0) continue;
        glm::dvec3 radiance = glm::dvec3(light.color) * double(light.intensity);
        if (light.type == LightType::spot) {
            const double cd = -glm::dot(glm::normalize(glm::dvec3(light.direction)), l_unit);
            const double inner = std::cos(double(light.inner_cone)), outer = std::cos(double(light.outer_cone));
            const double fade = std::clamp((cd - outer) / std::max(0.001, inner - outer), 0.0, 1.0);
            radiance *= fade * fade;
        }
        if (light.attenuate && !directional) radiance /= r2;
        if (diffuse_term) {
            sum += radiance * glm::dvec3(c.material.diffuse) * n_dot_l * visible;
        } else {
            const double lobe = glm::dot(n, glm::normalize(l_unit + v));
            sum += radiance * glm::dvec3(c.material.specular) * std::pow(std::max(lobe, 0.0), double(c.material.exponent)) *
                   visible;
        }
    }
    return sum;
}

TEST(LightingKernels, blinnPhongAgreesWithADoublePrecisionReference) {
    const Case c = random_case(11, 40.0f);
    const LightingBatch batch = lit(c, SpecularModel::blinn, true);
    // Float error: some 40 roundings of 2^-24 on the way to the lobe and the sums, and the lobe's relative error
    // multiplied by the exponent in lobe^n: (40 + n) 2^-24 relative, doubled for margin.
    const double relative = 2 * (40 + 40) * 0x1p-24;
    for (size_t j = 0; j < kLightingBatch; ++j) {
        const glm::dvec3 diffuse = reference_term(c, j, true), specular = reference_term(c, j, false);
        for (int k = 0; k < 3; ++k) {
            EXPECT_NEAR(batch.diffuse[k][j], diffuse[k], relative * std::abs(diffuse[k]) + 1e-7) << "point " << j;
            EXPECT_NEAR(batch.specular[k][j], specular[k], relative * std::abs(specular[k]) + 1e-7) << "point " << j;
        }
    }
}

}  // namespace
}  // namespace raster
