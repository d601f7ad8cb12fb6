// The precision model's formulas, each against its derivation in oracle/reference/precision.h.
#include "oracle/reference/precision.h"

#include <cmath>

#include <gtest/gtest.h>

#include "raster/geometry/setup.h"

namespace raster::oracle {
namespace {

TEST(Precision, theSnapMovesAVertexByHalfASubPixelPerCoordinate) {
    EXPECT_EQ(snap_displacement(8), 1.0 / 512.0);
    EXPECT_EQ(snap_displacement(1), 0.25);
    EXPECT_EQ(snap_displacement(16), std::ldexp(1.0, -17));
    // The snap itself: floor(x * 2^b + 0.5) / 2^b is never further than that from x.
    for (double x : {0.0, 0.1, 12.34567, 99.998046875 + 1e-9, 7.0 + 1.0 / 512.0}) {
        const double snapped = std::floor(x * 256.0 + 0.5) / 256.0;
        EXPECT_LE(std::fabs(snapped - x), snap_displacement(8)) << x;
    }
}

TEST(Precision, gammaIsHighamsBoundOnChainedRoundings) {
    const double u = std::ldexp(1.0, -24);
    EXPECT_EQ(kFloatUnitRoundoff, u);
    EXPECT_DOUBLE_EQ(float_gamma(1), u / (1 - u));
    EXPECT_DOUBLE_EQ(float_gamma(23), 23 * u / (1 - 23 * u));
    EXPECT_EQ(kVertexRoundings, 23);
    // A real 4-term float dot product stays inside gamma_4 |a|.|b|.
    const float a[4] = {1.1f, -2.3f, 3.7f, 1.0f}, b[4] = {0.3f, 0.77f, -1.9f, 5.5f};
    float product = 0.0f;
    double exact = 0.0, magnitude = 0.0;
    for (int i = 0; i < 4; ++i) {
        product += a[i] * b[i];
        exact += double(a[i]) * double(b[i]);
        magnitude += std::fabs(double(a[i]) * double(b[i]));
    }
    EXPECT_LE(std::fabs(product - exact), float_gamma(4) * magnitude);
}

TEST(Precision, aClippedVertexInheritsTheLargerEndpointErrorPlusItsOwnRounding) {
    // With exact plane distances (no slide), the cut inherits the larger endpoint error plus its rounding.
    const ClipEnd a{glm::dvec4(0.0), glm::dvec4(1e-6, 2e-6, 0, 3e-6), glm::dvec4(1, 2, 3, 4), 1.0, 0.0};
    const ClipEnd b{glm::dvec4(0.0), glm::dvec4(2e-6, 1e-6, 0, 1e-6), glm::dvec4(4, 3, 2, 1), -1.0, 0.0};
    const glm::dvec4 e = clip_step_error(a, b);
    const double g = float_gamma(kClipStepRoundings);
    EXPECT_DOUBLE_EQ(e.x, 2e-6 + 5 * g);
    EXPECT_DOUBLE_EQ(e.y, 2e-6 + 5 * g);
    EXPECT_DOUBLE_EQ(e.w, 3e-6 + 5 * g);
}

TEST(Precision, aShallowCrossingSlidesTheCutPointAlongThePlaneByTheDistanceErrorOverTheAngle) {
    // An edge crossing the near plane w = 1 at a shallow angle: w falls by 2e-3 over 100 units of x.
    const double near = 1.0;
    const glm::dvec4 a(0, 0, 0, near + 1e-3), b(100, 0, 0, near - 1e-3), e(1e-6, 1e-6, 0, 1e-6);
    const ClipEnd in{a, e, glm::abs(a), a.w - near, e.w}, out{b, e, glm::abs(b), b.w - near, e.w};
    const glm::dvec4 bound = clip_step_error(in, out);
    auto cut = [&](const glm::dvec4& p, const glm::dvec4& q) {
        const double t = (p.w - near) / ((p.w - near) - (q.w - near));
        return p + t * (q - p);
    };
    const glm::dvec4 exact = cut(a, b);
    double worst = 0.0;  // the cut's largest x move over the endpoints moved by +-e
    for (int corner = 0; corner < 16; ++corner) {
        auto sign = [&](int bit) { return corner & (1 << bit) ? 1.0 : -1.0; };
        const glm::dvec4 a_moved = a + glm::dvec4(sign(0) * e.x, 0, 0, sign(1) * e.w);
        const glm::dvec4 b_moved = b + glm::dvec4(sign(2) * e.x, 0, 0, sign(3) * e.w);
        worst = std::max(worst, std::fabs(cut(a_moved, b_moved).x - exact.x));
    }
    EXPECT_LE(worst, bound.x);
    EXPECT_LT(bound.x, 2.0 * worst) << "the bound is the slide itself, not a multiple of it";
    // Inheriting the endpoints' errors alone misses the slide by orders of magnitude.
    EXPECT_GT(worst, 1000.0 * (e.x + float_gamma(kClipStepRoundings) * (std::fabs(a.x) + std::fabs(b.x))));
}

TEST(Precision, screenErrorBoundsTheWorstPerturbationOfTheDivide) {
    const int width = 800, height = 600;
    const glm::dvec4 clip(0.3, -0.7, 0.5, 2.0), error(1e-5, 2e-5, 0, 3e-5);
    const glm::dvec2 bound = screen_error(clip, error, width, height);
    // The worst case moves x and w in opposite directions (x > 0) and y and w in the same (y < 0).
    const double exact_x = (clip.x / clip.w + 1) * 0.5 * width;
    const double worst_x = ((clip.x + error.x) / (clip.w - error.w) + 1) * 0.5 * width;
    EXPECT_LE(std::fabs(worst_x - exact_x), bound.x * (1 + 1e-9));  // the bound is exact: equal up to rounding
    EXPECT_GT(std::fabs(worst_x - exact_x), 0.99 * bound.x);  // and it is not loose
    const double exact_y = (1 - clip.y / clip.w) * 0.5 * height;
    const double worst_y = (1 - (clip.y - error.y) / (clip.w - error.w)) * 0.5 * height;
    EXPECT_LE(std::fabs(worst_y - exact_y), bound.y * (1 + 1e-9));
    EXPECT_GT(std::fabs(worst_y - exact_y), 0.99 * bound.y);
    // An error that can reach w = 0 bounds nothing.
    EXPECT_TRUE(std::isinf(screen_error(clip, glm::dvec4(0, 0, 0, 2.0), width, height).x));
}

TEST(Precision, perspectiveBarycentricsMoveByAtMostTwiceTheRelativeDepthError) {
    // b_i = (l_i / w_i) / sum(l_k / w_k): perturb each 1/w by +-rel in the worst directions and compare.
    const double rel = 1e-4, l[3] = {0.2, 0.3, 0.5}, w[3] = {1.0, 4.0, 9.0};
    double worst = 0.0;
    for (int signs = 0; signs < 8; ++signs) {
        double exact_sum = 0, sum = 0, weight[3], exact_weight[3];
        for (int k = 0; k < 3; ++k) {
            exact_weight[k] = l[k] / w[k];
            weight[k] = exact_weight[k] * (1 + ((signs >> k) & 1 ? rel : -rel));
            exact_sum += exact_weight[k];
            sum += weight[k];
        }
        for (int k = 0; k < 3; ++k) worst = std::max(worst, std::fabs(weight[k] / sum - exact_weight[k] / exact_sum));
    }
    EXPECT_LE(worst, barycentric_rounding(rel));
    EXPECT_GT(worst, 0.2 * (barycentric_rounding(rel) - float_gamma(kBarycentricRoundings)));
    EXPECT_TRUE(std::isinf(barycentric_rounding(1.0)));
}

TEST(Precision, viewDepthMovesByAtMostTheRelativeDepthError) {
    const double rel = 1e-4, l[3] = {0.2, 0.3, 0.5}, w[3] = {1.0, 4.0, 9.0};
    double exact = 0, low = 0;
    for (int k = 0; k < 3; ++k) {
        exact += l[k] / w[k];
        low += l[k] / w[k] * (1 - rel);
    }
    EXPECT_LE(std::fabs(1 / low - 1 / exact) / (1 / exact), view_depth_rounding(rel));
    EXPECT_GT(std::fabs(1 / low - 1 / exact) / (1 / exact), 0.99 * (view_depth_rounding(rel) - float_gamma(kViewDepthRoundings)));
}

TEST(Precision, reversedZErrorIsTheDerivativeOfZOverW) {
    const glm::dvec4 clip(0, 0, 0.4, 2.0), error(0, 0, 1e-6, 2e-6);
    const double exact = clip.z / clip.w, worst = (clip.z + error.z) / (clip.w - error.w);
    EXPECT_LE(std::fabs(worst - exact), reversed_z_error(clip, error));
    EXPECT_GT(std::fabs(worst - exact), 0.99 * (reversed_z_error(clip, error) - float_gamma(kReversedZRoundings)));
}


// Rows a = (1, 0, 1), b = (0, 1, 1), c = (x, 0, 1) in (x, y, w): det = 1 - x.
struct FacingRows {
    glm::dvec4 clip[3];
    glm::dvec4 error[3];
    explicit FacingRows(double x, double e) {
        clip[0] = {1, 0, 0, 1}, clip[1] = {0, 1, 0, 1}, clip[2] = {x, 0, 0, 1};
        for (glm::dvec4& r : error) r = glm::dvec4(e, e, 0, e);
    }
};

TEST(Precision, facingIsUncertainExactlyWhileTheDeterminantIsWithinTheBound) {
    const double e = 1e-6;
    const double bound = facing_uncertainty(FacingRows(1.0, e).clip, FacingRows(1.0, e).error);
    ASSERT_GT(bound, 0.0);
    // The bound hardly changes as x moves by about itself, so det = 1 - x just inside and outside it:
    const FacingRows inside(1.0 - bound * (1 - 1e-3), e), outside(1.0 - bound * (1 + 1e-3), e);
    EXPECT_TRUE(facing_is_uncertain(inside.clip, inside.error));
    EXPECT_FALSE(facing_is_uncertain(outside.clip, outside.error));
    // Either sign: a back face just as close to edge-on is uncertain as well.
    const FacingRows behind(1.0 + bound * (1 - 1e-3), e);
    EXPECT_TRUE(facing_is_uncertain(behind.clip, behind.error));
}

TEST(Precision, aVertexErrorWithinTheBoundFlipsRastersFacingDecision) {
    // Not a loose bound for nothing: moving the rows by less than their error turns a front face into a back face in
    // raster's own decision (raster/geometry/setup.h faces_front), so the comparator has to allow it.
    const double e = 1e-6;
    const FacingRows exact(1.0 - 1e-6, e);  // det = 1e-6 > 0: front-facing
    ASSERT_TRUE(faces_front(glm::vec4(exact.clip[0]), glm::vec4(exact.clip[1]), glm::vec4(exact.clip[2])));
    ASSERT_TRUE(facing_is_uncertain(exact.clip, exact.error));
    const glm::dvec4 moved_c = exact.clip[2] + glm::dvec4(e, 0, 0, -e) * 0.99;  // within e componentwise
    EXPECT_FALSE(faces_front(glm::vec4(exact.clip[0]), glm::vec4(exact.clip[1]), glm::vec4(moved_c)));
}

TEST(Precision, rastersFacingDecisionIsTheSignOfTheNdcArea) {
    // Counter-clockwise in NDC (y up) is front-facing; a positive w scale of any vertex changes nothing.
    const glm::vec4 a(-1, -1, 0, 1), b(1, -1, 0, 1), c(0, 1, 0, 1);
    EXPECT_TRUE(faces_front(a, b, c));
    EXPECT_FALSE(faces_front(a, c, b));
    EXPECT_TRUE(faces_front(a * 3.0f, b, c * 0.5f));
    // A triangle reaching behind the eye (w < 0 at one vertex) has the facing of its visible part, e.g. of the
    // piece cut at p on the edge from b to the vertex behind (p in NDC: (1.5, -0.5); the piece is counter-clockwise).
    const glm::vec4 behind(0, 2, 0, -1), p = 0.75f * b + 0.25f * behind;  // w = 0.5
    EXPECT_TRUE(faces_front(a, b, p));
    EXPECT_TRUE(faces_front(a, b, behind));
    EXPECT_FALSE(faces_front(b, a, behind));
}

TEST(Precision, embreesViewDepthErrorIsAFewRoundingsFaceOnAndGrowsAsTheTriangleTurnsEdgeOn) {
    const glm::dvec3 no_error[3] = {glm::dvec3(0.0), glm::dvec3(0.0), glm::dvec3(0.0)};
    const glm::dvec3 direction(0, 0, -1);
    // The plane z = -2 - k y through the hit at depth 2, over the same footprint in x and y: den (twice the area
    // seen along the ray) stays the same while the triangle's extent, and so the rounding of T and den, grows.
    auto triangle_at = [](double k, glm::dvec3 (&v)[3]) {
        v[0] = {-1, -1, -2 + k};
        v[1] = {1, -1, -2 + k};
        v[2] = {0, 1, -2 - k};
    };
    glm::dvec3 face_on[3];
    triangle_at(0.0, face_on);
    const double face_on_error = embree_view_depth_error(face_on, no_error, direction, 2.0);
    EXPECT_GT(face_on_error, 0.0);
    EXPECT_LT(face_on_error, 2.0 * float_gamma(40));  // a few dozen float roundings of t
    double previous = face_on_error;
    for (double k : {10.0, 100.0, 1000.0}) {
        glm::dvec3 turned[3];
        triangle_at(k, turned);
        const double error = embree_view_depth_error(turned, no_error, direction, 2.0);
        EXPECT_GT(error, 5.0 * previous) << k;
        previous = error;
    }
    // The vertices' own errors count: 1e-6 of them moves the plane, and the bound, further.
    const glm::dvec3 off[3] = {glm::dvec3(1e-6), glm::dvec3(1e-6), glm::dvec3(1e-6)};
    EXPECT_GT(embree_view_depth_error(face_on, off, direction, 2.0), 1e-6);
    // Seen exactly edge-on, den is 0: unbounded.
    const glm::dvec3 edge_on[3] = {{-1, 0, -2}, {1, 0, -2}, {0, 0, -3}};
    EXPECT_TRUE(std::isinf(embree_view_depth_error(edge_on, no_error, direction, 2.0)));
}

TEST(Precision, embreeMayCoverARayExactlyWhileEachEdgeIsWithinItsUncertainty) {
    // A fat triangle at depth 1 with the ray along -z through (x, 0.25): the edge x = 0 (from v0 to v2) decides.
    const glm::dvec3 v[3] = {{0, 0, -1}, {1, 0, -1}, {0, 1, -1}};
    const glm::dvec3 error[3] = {glm::dvec3(1e-7), glm::dvec3(1e-7), glm::dvec3(1e-7)};
    auto ray = [](double x) { return glm::dvec3(x, 0.25, -1.0); };
    EXPECT_TRUE(embree_may_cover(v, error, ray(0.25)));
    // The edge x = 0 has U = 2 dot(v2 x v0, D) = -2 x: how far outside can the ray go? To the uncertainty plus slack.
    // Just outside (x = -d), U = 2 d > 0 while V = -0.5 and W = -2 (d + 0.75) stay negative: Embree may cover the
    // ray while U is within its uncertainty plus Embree's slack, 2u (1 + gamma_3) (|U| + |V| + |W| + the bounds).
    const glm::dvec3 bound = embree_edge_uncertainty(v, error, ray(0.0));
    ASSERT_GT(bound.x, 0.0);
    ASSERT_LT(bound.x, 1e-5);
    const double slack =
        2.0 * kFloatUnitRoundoff * (1.0 + float_gamma(3)) * (0.5 + 1.5 + bound.x + bound.y + bound.z);
    const double limit = 0.5 * (bound.x + slack);  // the largest d
    EXPECT_TRUE(embree_may_cover(v, error, ray(-limit * (1 - 1e-2))));
    EXPECT_FALSE(embree_may_cover(v, error, ray(-limit * (1 + 1e-2))));
    EXPECT_FALSE(embree_may_cover(v, error, ray(-1e-3)));
    // Either orientation: the same triangle wound the other way.
    const glm::dvec3 reversed[3] = {v[0], v[2], v[1]};
    EXPECT_TRUE(embree_may_cover(reversed, error, ray(0.25)));
    EXPECT_FALSE(embree_may_cover(reversed, error, ray(-1e-3)));
}

TEST(Precision, embreeMayCoverANeedleAlongItsLineBeyondItsTip) {
    // A needle 1e-6 wide along the line y = 0, z = -5, its tip at x = -1: the signs of its two long edges are
    // uncertain for every ray that meets that line, also beyond the tip, and its short edge's sign is uncertain too.
    const glm::dvec3 v[3] = {{-10, 0, -5}, {-10, 1e-6, -5}, {-1, 0, -5}};
    const glm::dvec3 error[3] = {glm::dvec3(1e-6), glm::dvec3(1e-6), glm::dvec3(1e-6)};
    EXPECT_TRUE(embree_may_cover(v, error, glm::dvec3(-0.8, 0, -5)));   // through the needle
    EXPECT_TRUE(embree_may_cover(v, error, glm::dvec3(1, 0, -5)));      // 2 beyond the tip, on its line
    EXPECT_FALSE(embree_may_cover(v, error, glm::dvec3(1, 0.5, -5)));   // off the line
    EXPECT_FALSE(embree_may_cover(v, error, glm::dvec3(-5, 0.5, -5)));  // beside the needle
}

TEST(Precision, embreeMayMissARayTheTriangleExactlyCoversOnlyWithinAnEdgesUncertainty) {
    // The fat triangle of the test above: inside is x > 0, where U = -2 x < 0 and V, W < 0. Embree surely reports
    // the hit once -U >= B_U, that is x >= B_U / 2; nearer the edge it may miss it.
    const glm::dvec3 v[3] = {{0, 0, -1}, {1, 0, -1}, {0, 1, -1}};
    const glm::dvec3 error[3] = {glm::dvec3(1e-7), glm::dvec3(1e-7), glm::dvec3(1e-7)};
    auto ray = [](double x) { return glm::dvec3(x, 0.25, -1.0); };
    const double limit = 0.5 * embree_edge_uncertainty(v, error, ray(0.0)).x;
    EXPECT_FALSE(embree_may_miss(v, error, ray(0.25)));
    EXPECT_TRUE(embree_may_miss(v, error, ray(limit * (1 - 1e-2))));
    EXPECT_FALSE(embree_may_miss(v, error, ray(limit * (1 + 1e-2))));
    const glm::dvec3 reversed[3] = {v[0], v[2], v[1]};
    EXPECT_FALSE(embree_may_miss(reversed, error, ray(0.25)));
    // The differential fuzzer's case (rounded): one vertex far out, at 5e5, beside two of magnitude 10 to 30,
    // each vertex within gamma_8 of its magnitude (the oracle's float view transform). Embree's Pluecker value of
    // an edge to the far vertex, 2 dot((v_b - v_a) x (v_b + v_a), D), sums products of two of its large
    // components that cancel down to |v_a| |v_b|: its float error is about u 1e11, against values of 1e3 near that
    // edge. A ray 3e-4 (in barycentrics) inside such an edge may be missed; with the far vertex brought in to
    // magnitude 50, the same barycentrics are surely hit.
    auto oracle_errors = [](const glm::dvec3 (&p)[3], glm::dvec3 (&e)[3]) {
        for (int k = 0; k < 3; ++k) e[k] = float_gamma(8) * glm::abs(p[k]);
    };
    auto point = [](const glm::dvec3 (&p)[3], const glm::dvec3& bary) {
        return bary.x * p[0] + bary.y * p[1] + bary.z * p[2];
    };
    const glm::dvec3 bary(1.3e-5, 1.0 - 1.3e-5 - 2.7e-4, 2.7e-4);
    const glm::dvec3 far_out[3] = {{-292188, 224038, -373261}, {-3.90337, -0.579734, -8.96375},
                                   {3.84151, -4.19157, -27.7218}};
    const glm::dvec3 near_by[3] = {1e-4 * far_out[0], far_out[1], far_out[2]};
    glm::dvec3 far_error[3], near_error[3];
    oracle_errors(far_out, far_error);
    oracle_errors(near_by, near_error);
    EXPECT_TRUE(embree_may_miss(far_out, far_error, point(far_out, bary)));
    EXPECT_FALSE(embree_may_miss(near_by, near_error, point(near_by, bary)));
    // Near that sample the uncertainty is 3% of the values' sum, so a sample 10% inside the same edge is surely hit.
    EXPECT_FALSE(embree_may_miss(far_out, far_error, point(far_out, glm::dvec3(1.3e-5, 0.9 - 1.3e-5, 0.1))));
}

}  // namespace
}  // namespace raster::oracle
