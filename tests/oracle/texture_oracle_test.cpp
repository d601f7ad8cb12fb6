// The oracle's texture model against raster's texture code and against its own derivations: its mip chain against
// raster's within texel_error, its filter boxes holding raster's lookups, its ray differentials against finite
// differences, and the derivative bound sound against perturbed vertices and not loose by more than a small factor.
#include <cmath>
#include <memory>
#include <random>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>
#include <gtest/gtest.h>

#include "oracle/reference/texture_filters.h"
#include "oracle/reference/texture_precision.h"
#include "oracle/reference/texture_sampling.h"
#include "raster/texture/texture_sampler.h"

namespace raster::oracle {
namespace {

struct Pair {
    std::shared_ptr<Texture> raster;
    OracleTexture oracle;
};

// The same random 8-bit image as raster's texture (its chain built by raster) and as the oracle's (its own chain).
Pair random_texture(std::mt19937& rng, int width, int height) {
    std::uniform_int_distribution<int> code(0, 255);
    Pair p;
    p.raster = std::make_shared<Texture>();
    TextureLevel level;
    OracleTextureLevel exact;
    level.width = exact.width = width;
    level.height = exact.height = height;
    for (int i = 0; i < width * height; ++i) {
        const int r = code(rng), g = code(rng), b = code(rng);
        level.texels.emplace_back(r / 255.0f, g / 255.0f, b / 255.0f);
        exact.texels.emplace_back(r / 255.0, g / 255.0, b / 255.0);
    }
    exact.min = glm::dvec3(0.0);
    exact.max = glm::dvec3(1.0);
    p.raster->levels.push_back(level);
    build_mip_chain(*p.raster);
    p.oracle.levels.push_back(exact);
    while (p.oracle.levels.back().width > 1 || p.oracle.levels.back().height > 1)
        p.oracle.levels.push_back(next_oracle_level(p.oracle.levels.back()));
    return p;
}

TEST(OracleTexture, itsChainMatchesRastersWithinTheTexelError) {
    std::mt19937 rng(7);
    for (auto [w, h] : {std::pair{5, 3}, {120, 90}, {1, 17}, {64, 64}, {33, 2}}) {
        const Pair p = random_texture(rng, w, h);
        ASSERT_EQ(p.raster->levels.size(), p.oracle.levels.size());
        for (size_t k = 0; k < p.oracle.levels.size(); ++k) {
            const OracleTextureLevel& exact = p.oracle.levels[k];
            ASSERT_EQ(p.raster->levels[k].width, exact.width);
            ASSERT_EQ(p.raster->levels[k].height, exact.height);
            for (size_t i = 0; i < exact.texels.size(); ++i)
                for (int c = 0; c < 3; ++c)
                    ASSERT_LE(std::fabs(p.raster->levels[k].texels[i][c] - exact.texels[i][c]), texel_error(int(k), 1.0))
                        << w << "x" << h << " level " << k;
        }
    }
}

// For point inputs (boxes of width 0), raster's lookup lies in the oracle's box, for every filter and wrap, and the
// box is narrow where the inputs are away from the filters' discontinuities.
TEST(OracleTexture, itsFilterBoxesHoldRastersLookups) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> coordinate(-3.0, 3.0), derivative(-0.2, 0.2);
    const Pair p = random_texture(rng, 37, 20);
    int narrow = 0, total = 0;
    for (TextureFilter filter : {TextureFilter::nearest, TextureFilter::bilinear, TextureFilter::trilinear,
                                 TextureFilter::anisotropic}) {
        for (TextureWrap wrap : {TextureWrap::repeat, TextureWrap::clamp, TextureWrap::mirror}) {
            TextureBinding binding;
            binding.filter = filter;
            binding.wrap = wrap;
            binding.max_anisotropy = 8;
            binding.texture = p.raster;
            for (int n = 0; n < 300; ++n) {
                const glm::vec2 uv(coordinate(rng), coordinate(rng));
                const glm::vec2 dx(derivative(rng), derivative(rng)), dy(derivative(rng), derivative(rng));
                const glm::vec3 value = sample_texture(*binding.texture, sampler_of(binding), uv, dx, dy);
                TextureFootprintBox box;
                box.uv = {Interval(uv.x), Interval(uv.y)};
                box.d_dx = {Interval(dx.x), Interval(dx.y)};
                box.d_dy = {Interval(dy.x), Interval(dy.y)};
                const Interval3 allowed = filtered_over(p.oracle, sampler_of(binding), box);
                for (int c = 0; c < 3; ++c) {
                    ASSERT_LE(allowed[c].lo, value[c]) << to_string(filter) << " " << to_string(wrap) << " uv " << uv.x << " " << uv.y;
                    ASSERT_GE(allowed[c].hi, value[c]) << to_string(filter) << " " << to_string(wrap) << " uv " << uv.x << " " << uv.y;
                }
                narrow += allowed.x.hi - allowed.x.lo < 1e-4;
                ++total;
            }
        }
    }
    EXPECT_GT(narrow, total * 9 / 10);  // boxes of points are points, but for nearest's texel edges and tap counts
}

OracleCamera test_camera() {
    Camera camera;
    camera.eye = {0.3f, 1.5f, 4.0f};
    camera.target = {0.0f, 0.0f, -2.0f};
    return oracle_camera(camera, 320, 200);
}

// The ray differential against central differences of the exact ray-plane barycentrics at neighbouring pixels.
TEST(OracleTexture, rayDifferentialsMatchFiniteDifferences) {
    const OracleCamera camera = test_camera();
    const glm::dvec3 world[3] = {{-2.0, -0.5, -1.0}, {3.0, -0.7, -6.0}, {0.5, 2.0, -9.0}};
    glm::dvec3 view[3];
    for (int k = 0; k < 3; ++k) view[k] = view_of_world(camera, world[k]);
    const glm::dvec2 uv[3] = {{0.0, 0.0}, {4.0, 1.0}, {-1.0, 3.0}};
    // Exact barycentrics where the ray through a screen point meets the plane: solve P = t D = sum b_i v_i.
    auto bary_at = [&](const glm::dvec2& screen) {
        const glm::dvec3 d = ray_direction(camera, screen);
        const glm::dmat3 m(view[0], view[1], view[2]);  // sum b_i v_i = t d with sum b_i = 1
        const glm::dvec3 s = glm::inverse(m) * d;        // b = t s, t = 1 / (1 . s)
        return s / (s.x + s.y + s.z);
    };
    for (const glm::dvec2 screen : {glm::dvec2(100.5, 80.5), glm::dvec2(200.25, 40.75), glm::dvec2(150.0, 150.0)}) {
        const glm::dvec3 b = bary_at(screen);
        const UvDerivatives d = ray_differential(camera, view, uv, b);
        const double h = 1e-3;
        const glm::dvec3 fx = (bary_at(screen + glm::dvec2(h, 0)) - bary_at(screen - glm::dvec2(h, 0))) / (2 * h);
        const glm::dvec3 fy = (bary_at(screen + glm::dvec2(0, h)) - bary_at(screen - glm::dvec2(0, h))) / (2 * h);
        for (int i = 0; i < 3; ++i) {
            EXPECT_NEAR(d.dbary_dx[i], fx[i], 1e-7 + 1e-5 * std::fabs(fx[i])) << i;
            EXPECT_NEAR(d.dbary_dy[i], fy[i], 1e-7 + 1e-5 * std::fabs(fy[i])) << i;
        }
    }
}

// raster's derivative g = W (c - b (1 . c)) from vertices moved anywhere in their error boxes stays inside the
// bound, and the worst of the box's corners reaches a fair share of it (the bound is not loose by orders).
TEST(OracleTexture, theDerivativeBoundHoldsAndIsReached) {
    DerivativeErrorInputs in;
    in.width = 640;
    in.height = 480;
    in.clip[0] = {-0.4, -0.3, 0.9, 2.0};
    in.clip[1] = {1.2, -0.6, 0.95, 7.0};
    in.clip[2] = {0.1, 1.4, 0.97, 11.0};
    for (int k = 0; k < 3; ++k) in.clip_error[k] = glm::dvec4(1e-6) * glm::abs(in.clip[k]);
    const glm::dvec3 bary(0.2, 0.5, 0.3), bary_error(1e-7);
    auto gradient = [&](const glm::dvec4 clip[3], const glm::dvec3& b) {
        glm::dmat3 m;
        for (int k = 0; k < 3; ++k)
            m[k] = {(clip[k].x + clip[k].w) * in.width / 2, (clip[k].w - clip[k].y) * in.height / 2, clip[k].w};
        const glm::dmat3 inverse = glm::inverse(m);
        const double w = clip[0].w * b.x + clip[1].w * b.y + clip[2].w * b.z;
        const glm::dvec3 c = inverse[0];
        return w * (c - b * (c.x + c.y + c.z));
    };
    const glm::dvec3 exact = gradient(in.clip, bary);
    const GradientError bound = gradient_error(in, bary, bary_error);
    double worst = 0.0, bound_max = 0.0;
    std::mt19937 rng(3);
    std::uniform_int_distribution<int> sign(0, 1);
    for (int trial = 0; trial < 4000; ++trial) {
        glm::dvec4 moved[3];
        for (int k = 0; k < 3; ++k)
            for (int c = 0; c < 4; ++c) moved[k][c] = in.clip[k][c] + (sign(rng) ? 1 : -1) * in.clip_error[k][c];
        glm::dvec3 b = bary;
        for (int i = 0; i < 3; ++i) b[i] += (sign(rng) ? 1 : -1) * bary_error[i];
        const glm::dvec3 g = gradient(moved, b);
        for (int i = 0; i < 3; ++i) {
            ASSERT_LE(std::fabs(g[i] - exact[i]), bound.x[i]) << "component " << i;
            worst = std::max(worst, std::fabs(g[i] - exact[i]) / bound.x[i]);
        }
    }
    for (int i = 0; i < 3; ++i) bound_max = std::max(bound_max, bound.x[i]);
    EXPECT_GT(worst, 1.0 / 16.0) << "the bound is more than 16 times the largest error seen";
}

}  // namespace
}  // namespace raster::oracle
