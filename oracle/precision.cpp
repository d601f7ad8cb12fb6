// The precision model's formulas; the derivations are next to the declarations in precision.h.
#include "oracle/precision.h"

#include <cmath>
#include <limits>

#include <glm/common.hpp>

namespace raster::oracle {

double snap_displacement(int snap_bits) { return std::ldexp(1.0, -(snap_bits + 1)); }

glm::dvec4 vertex_error(const glm::dvec4& magnitudes) { return float_gamma(kVertexRoundings) * magnitudes; }

glm::dvec4 clip_step_error(const glm::dvec4& error_a, const glm::dvec4& error_b, const glm::dvec4& magnitudes_a,
                           const glm::dvec4& magnitudes_b) {
    return glm::max(error_a, error_b) + float_gamma(kClipStepRoundings) * (magnitudes_a + magnitudes_b);
}

glm::dvec2 screen_error(const glm::dvec4& clip, const glm::dvec4& error, int width, int height) {
    const double denominator = clip.w - error.w;
    if (!(denominator > 0.0)) return glm::dvec2(std::numeric_limits<double>::infinity());
    return {0.5 * width * (error.x + std::fabs(clip.x / clip.w) * error.w) / denominator,
            0.5 * height * (error.y + std::fabs(clip.y / clip.w) * error.w) / denominator};
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
