// The texture precision model's bounds (texture_precision.h).
#include "oracle/reference/texture_precision.h"

#include <cmath>
#include <limits>

#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include "oracle/reference/precision.h"

namespace raster::oracle {

double texel_error(int level, double magnitude) {
    return float_gamma(kTexelRoundingsAtLevelZero + level) * magnitude;
}

namespace {

double frobenius(const glm::dmat3& m) {
    double sum = 0.0;
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) sum += m[c][r] * m[c][r];
    return std::sqrt(sum);
}

double sum_abs(const glm::dvec3& v) { return std::fabs(v.x) + std::fabs(v.y) + std::fabs(v.z); }

}  // namespace

GradientError gradient_error(const DerivativeErrorInputs& in, const glm::dvec3& bary, const glm::dvec3& bary_error) {
    const double inf = std::numeric_limits<double>::infinity();
    GradientError out{glm::dvec3(inf), glm::dvec3(inf)};
    const double half_w = 0.5 * in.width, half_h = 0.5 * in.height;
    glm::dmat3 m, dm;
    for (int k = 0; k < 3; ++k) {
        const glm::dvec4& c = in.clip[k];
        const glm::dvec4& e = in.clip_error[k];
        m[k] = glm::dvec3((c.x + c.w) * half_w, (c.w - c.y) * half_h, c.w);
        dm[k] = glm::dvec3((e.x + e.w) * half_w, (e.w + e.y) * half_h, e.w);
    }
    const double det = glm::determinant(m);
    if (!(std::fabs(det) > 0.0) || !std::isfinite(det)) return out;
    const glm::dmat3 inverse = glm::inverse(m);
    const double norm = frobenius(m), inverse_norm = frobenius(inverse);
    const double k_e = norm * inverse_norm * (frobenius(dm) / norm);
    if (!(k_e < 0.5)) return out;
    glm::dmat3 inverse_magnitude;
    for (int c = 0; c < 3; ++c) inverse_magnitude[c] = glm::abs(inverse[c]);
    glm::dvec3 w(in.clip[0].w, in.clip[1].w, in.clip[2].w), w_error(in.clip_error[0].w, in.clip_error[1].w, in.clip_error[2].w);
    const double W = glm::dot(w, bary);
    const double dW = glm::dot(glm::abs(w), bary_error) + glm::dot(w_error, glm::abs(bary)) +
                      float_gamma(kWeightRoundings) * glm::dot(glm::abs(w), glm::abs(bary));
    auto column_error = [&](const glm::dvec3& c) {
        // Column j of d(M^-1) = -M^-1 dM M^-1 e_j = -M^-1 dM c_j: componentwise within |M^-1| |dM| |c_j|, over
        // (1 - k e) for the higher orders; plus its float storage.
        const glm::dvec3 dc = (inverse_magnitude * (dm * glm::abs(c))) / (1.0 - k_e) +
                              float_gamma(kColumnRoundings) * glm::abs(c);
        const double s = c.x + c.y + c.z;
        const double ds = sum_abs(dc) + float_gamma(2) * sum_abs(c);
        glm::dvec3 dg;
        for (int i = 0; i < 3; ++i)
            dg[i] = std::fabs(W) * (dc[i] + bary_error[i] * std::fabs(s) + std::fabs(bary[i]) * ds) +
                    dW * std::fabs(c[i] - bary[i] * s) +
                    float_gamma(kGradientRoundings) * std::fabs(W) * (std::fabs(c[i]) + std::fabs(bary[i]) * std::fabs(s));
        return dg;
    };
    out.x = column_error(inverse[0]);
    out.y = column_error(inverse[1]);
    return out;
}

}  // namespace raster::oracle
