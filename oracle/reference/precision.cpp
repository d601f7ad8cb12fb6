// The precision model's formulas; the derivations are next to the declarations in precision.h.
#include "oracle/reference/precision.h"

#include <cmath>
#include <limits>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace raster::oracle {

double snap_displacement(int snap_bits) { return std::ldexp(1.0, -(snap_bits + 1)); }

glm::dvec4 vertex_error(const glm::dvec4& magnitudes) { return float_gamma(kVertexRoundings) * magnitudes; }

double plane_noise(const glm::dvec3& edge1, const glm::dvec3& edge2, double vertex_magnitude) {
    const double delta = double_gamma(kOracleDoubleViewRoundings) * vertex_magnitude;
    const double e1 = glm::length(edge1), e2 = glm::length(edge2);
    return 2.0 * delta * (e1 + e2 + 2.0 * delta) + double_gamma(4) * e1 * e2;
}

glm::dvec4 clip_step_error(const ClipEnd& a, const ClipEnd& b) {
    const double gap = std::fabs(a.distance - b.distance);
    const double slack = gap - a.distance_error - b.distance_error;
    if (!(slack > 0.0)) return glm::dvec4(std::numeric_limits<double>::infinity());
    const double dt = (std::fabs(a.distance) * b.distance_error + a.distance_error * std::fabs(b.distance)) / (gap * slack);
    return glm::max(a.error, b.error) + dt * glm::abs(b.clip - a.clip) +
           float_gamma(kClipStepRoundings) * (a.magnitudes + b.magnitudes);
}

glm::dvec2 screen_error(const glm::dvec4& clip, const glm::dvec4& error, int width, int height) {
    const double denominator = clip.w - error.w;
    if (!(denominator > 0.0)) return glm::dvec2(std::numeric_limits<double>::infinity());
    return {0.5 * width * (error.x + std::fabs(clip.x / clip.w) * error.w) / denominator,
            0.5 * height * (error.y + std::fabs(clip.y / clip.w) * error.w) / denominator};
}

namespace {

// dot(|a| x| |b|, |d|): the magnitude of dot(cross(a, b), d) summed term by term.
double cross_dot_magnitude(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& d) {
    const glm::dvec3 x = glm::abs(a), y = glm::abs(b), z = glm::abs(d);
    return (x.y * y.z + x.z * y.y) * z.x + (x.z * y.x + x.x * y.z) * z.y + (x.x * y.y + x.y * y.x) * z.z;
}

// |a| x| |b|: the componentwise magnitude of cross(a, b), its two products added.
glm::dvec3 cross_magnitude(const glm::dvec3& a, const glm::dvec3& b) {
    const glm::dvec3 x = glm::abs(a), y = glm::abs(b);
    return {x.y * y.z + x.z * y.y, x.z * y.x + x.x * y.z, x.x * y.y + x.y * y.x};
}

}  // namespace

glm::dvec3 embree_barycentric_error(const glm::dvec3 v[3], const glm::dvec3& direction, const glm::dvec3& bary) {
    // U pairs with v1 (its edge runs v0 -> v2), V with v2 (edge v1 -> v0), W with v0 (edge v2 -> v1).
    const double m_u = cross_dot_magnitude(v[2] - v[0], v[2] + v[0], direction);
    const double m_v = cross_dot_magnitude(v[0] - v[1], v[0] + v[1], direction);
    const double m_w = cross_dot_magnitude(v[1] - v[2], v[1] + v[2], direction);
    // U + V + W = 2 dot(cross(v1 - v0, v2 - v0), D) exactly (the vertex cross products telescope).
    const double s = 2.0 * std::fabs(glm::dot(glm::cross(v[1] - v[0], v[2] - v[0]), direction));
    const double e_s = float_gamma(kEmbreeEdgeRoundings + kEmbreeSumRoundings) * (m_u + m_v + m_w);
    if (!(e_s < s)) return glm::dvec3(std::numeric_limits<double>::infinity());
    const double g = float_gamma(kEmbreeEdgeRoundings), ratio = float_gamma(kEmbreeRatioRoundings);
    const double u = std::fabs(bary.y), w = std::fabs(bary.z);
    const double error_u = (g * m_u + u * e_s) / (s - e_s) + ratio * u;
    const double error_v = (g * m_v + w * e_s) / (s - e_s) + ratio * w;
    const double error_first = error_u + error_v + float_gamma(kOracleBarycentricRoundings) * (1.0 + u + w);
    return {error_first, error_u, error_v};
}

namespace {

// Embree's U, V, W for the ray from the eye along `direction`, exactly: U pairs with v1 (its edge runs v0 -> v2),
// V with v2 (edge v1 -> v0), W with v0 (edge v2 -> v1); each is dot(cross(b - a, b + a), D) = 2 dot(b x a, D).
glm::dvec3 pluecker_values(const glm::dvec3 v[3], const glm::dvec3& direction) {
    return 2.0 * glm::dvec3(glm::dot(glm::cross(v[2], v[0]), direction), glm::dot(glm::cross(v[0], v[1]), direction),
                            glm::dot(glm::cross(v[1], v[2]), direction));
}

// How far 2 dot(b x a, D) moves when a and b move by at most ea and eb componentwise.
double pluecker_vertex_error(const glm::dvec3& a, const glm::dvec3& ea, const glm::dvec3& b, const glm::dvec3& eb,
                             const glm::dvec3& direction) {
    return 2.0 * (cross_dot_magnitude(eb, glm::abs(a) + ea, direction) + cross_dot_magnitude(b, ea, direction));
}

}  // namespace

glm::dvec3 embree_edge_uncertainty(const glm::dvec3 v[3], const glm::dvec3 error[3], const glm::dvec3& direction) {
    const double g = float_gamma(kEmbreeEdgeRoundings);
    auto edge = [&](int a, int b) {  // the value 2 dot(v_b x v_a, D) of the edge a -> b
        // Embree's float difference and sum of the oracle's vertices, in magnitude.
        const glm::dvec3 moved = error[a] + error[b];
        return pluecker_vertex_error(v[a], error[a], v[b], error[b], direction) +
               g * cross_dot_magnitude(glm::abs(v[b] - v[a]) + moved, glm::abs(v[b] + v[a]) + moved, direction);
    };
    return {edge(0, 2), edge(1, 0), edge(2, 1)};
}

bool embree_may_cover(const glm::dvec3 v[3], const glm::dvec3 error[3], const glm::dvec3& direction) {
    const glm::dvec3 values = pluecker_values(v, direction);
    const glm::dvec3 uncertainty = embree_edge_uncertainty(v, error, direction);
    const double slack = 2.0 * kFloatUnitRoundoff * (1.0 + float_gamma(3)) *
                         (std::fabs(values.x) + std::fabs(values.y) + std::fabs(values.z) + uncertainty.x +
                          uncertainty.y + uncertainty.z);
    const glm::dvec3 allowance = uncertainty + glm::dvec3(slack);
    const bool all_positive = values.x >= -allowance.x && values.y >= -allowance.y && values.z >= -allowance.z;
    const bool all_negative = values.x <= allowance.x && values.y <= allowance.y && values.z <= allowance.z;
    return all_positive || all_negative;
}

bool embree_may_miss(const glm::dvec3 v[3], const glm::dvec3 error[3], const glm::dvec3& direction) {
    const glm::dvec3 values = pluecker_values(v, direction);
    const glm::dvec3 uncertainty = embree_edge_uncertainty(v, error, direction);
    const bool surely_positive = values.x >= uncertainty.x && values.y >= uncertainty.y && values.z >= uncertainty.z;
    const bool surely_negative = values.x <= -uncertainty.x && values.y <= -uncertainty.y && values.z <= -uncertainty.z;
    return !(surely_positive || surely_negative);
}

double embree_view_depth_error(const glm::dvec3 v[3], const glm::dvec3 error[3], const glm::dvec3& direction,
                               double view_depth) {
    const double u = kFloatUnitRoundoff;
    // Ng is the cross product of two edges that Embree forms from the oracle's vertices; any two give the same
    // exact normal (up to sign, which den and T share), so the bound takes the worst pair. An edge is off by the
    // vertex errors of its ends plus the subtraction's rounding.
    auto edge = [&](int from, int to, glm::dvec3& exact, glm::dvec3& off) {
        exact = v[to] - v[from];
        const glm::dvec3 moved = error[from] + error[to];
        off = moved + u * (glm::abs(exact) + moved);
    };
    const glm::dvec3 normal = glm::cross(v[1] - v[0], v[2] - v[0]);
    glm::dvec3 normal_error(0.0);
    for (int k = 0; k < 3; ++k) {
        glm::dvec3 a, a_off, b, b_off;
        edge(k, (k + 1) % 3, a, a_off);
        edge((k + 1) % 3, (k + 2) % 3, b, b_off);
        const glm::dvec3 a_bound = glm::abs(a) + a_off, b_bound = glm::abs(b) + b_off;
        normal_error = glm::max(normal_error, cross_magnitude(a_off, b_bound) + cross_magnitude(a, b_off) +
                                                  float_gamma(kEmbreeCrossRoundings) * cross_magnitude(a_bound, b_bound));
    }
    const glm::dvec3 normal_bound = glm::abs(normal) + normal_error;
    const glm::dvec3 d = glm::abs(direction);
    // den = 2 dot(Ng, D) and T = 2 dot(v0, Ng); D itself is rounded to float (u |D|).
    const double den = 2.0 * glm::dot(normal, direction);
    const double den_error = 2.0 * (glm::dot(normal_error, d) + u * glm::dot(normal_bound, d) +
                                    float_gamma(kEmbreeDotRoundings) * (1.0 + u) * glm::dot(normal_bound, d));
    const glm::dvec3 v0_bound = glm::abs(v[0]) + error[0];
    const double t_numerator_error = 2.0 * (glm::dot(error[0], normal_bound) + glm::dot(glm::abs(v[0]), normal_error) +
                                            float_gamma(kEmbreeDotRoundings) * glm::dot(v0_bound, normal_bound));
    if (!(den_error < std::fabs(den))) return std::numeric_limits<double>::infinity();
    const double t = std::fabs(view_depth);
    const double quotient_error = (t_numerator_error + t * den_error) / (std::fabs(den) - den_error);
    return quotient_error + float_gamma(kEmbreeRatioRoundings) * (t + quotient_error);
}

double facing_uncertainty(const glm::dvec4 clip[3], const glm::dvec4 error[3]) {
    double exact = 1.0, moved = 1.0, moved_sum_norm = 1.0;
    for (int i = 0; i < 3; ++i) {
        const glm::dvec3 row(clip[i].x, clip[i].y, clip[i].w), row_error(error[i].x, error[i].y, error[i].w);
        exact *= glm::length(row);
        moved *= glm::length(row) + glm::length(row_error);
        moved_sum_norm *= std::fabs(row.x) + std::fabs(row.y) + std::fabs(row.z) + row_error.x + row_error.y + row_error.z;
    }
    return (moved - exact) + double_gamma(kFacingDoubleRoundings) * moved_sum_norm;
}

bool facing_is_uncertain(const glm::dvec4 clip[3], const glm::dvec4 error[3]) {
    const glm::dvec3 a(clip[0].x, clip[0].y, clip[0].w), b(clip[1].x, clip[1].y, clip[1].w), c(clip[2].x, clip[2].y, clip[2].w);
    const double determinant = glm::dot(a, glm::cross(b, c));
    return !(std::fabs(determinant) > facing_uncertainty(clip, error));
}

double relative_depth_error(double w, double w_error) {
    const double denominator = w - w_error;
    return denominator > 0.0 ? w_error / denominator : std::numeric_limits<double>::infinity();
}

double barycentric_rounding(double relative_depth_error) {
    if (!(relative_depth_error < 1.0)) return std::numeric_limits<double>::infinity();
    return 2.0 * relative_depth_error / (1.0 - relative_depth_error) + float_gamma(kBarycentricRoundings);
}

double view_depth_rounding(double relative_depth_error) {
    if (!(relative_depth_error < 1.0)) return std::numeric_limits<double>::infinity();
    return relative_depth_error / (1.0 - relative_depth_error) + float_gamma(kViewDepthRoundings);
}

double reversed_z_error(const glm::dvec4& clip, const glm::dvec4& error) {
    const double denominator = clip.w - error.w;
    if (!(denominator > 0.0)) return std::numeric_limits<double>::infinity();
    return (error.z + std::fabs(clip.z / clip.w) * error.w) / denominator + float_gamma(kReversedZRoundings);
}

}  // namespace raster::oracle
