// Sample positions in pixels and camera rays through screen points, solved from the projection matrix.
#include "raster/geometry/camera_rays.h"

#include <cmath>

namespace raster {

glm::dvec2 sample_screen_position(int px, int py, int sample, const FixedSampleOffsets& offsets, int fixed_bits) {
    const FixedPosition p = sample_fixed_position(px, py, sample, offsets, fixed_bits);
    return {std::ldexp(static_cast<double>(p.x), -fixed_bits), std::ldexp(static_cast<double>(p.y), -fixed_bits)};
}

glm::dvec3 view_ray_direction(const glm::mat4& projection, const glm::dvec2& ndc) {
    // The view point (x, y, -1) projects to clip = P (x, y, -1, 1). Requiring clip.x = ndc.x * clip.w and
    // clip.y = ndc.y * clip.w gives two linear equations in x and y (GLM is column-major: P[col][row]).
    auto p = [&](int col, int row) { return static_cast<double>(projection[col][row]); };
    const double w_const = -p(2, 3) + p(3, 3);
    const double a00 = p(0, 0) - ndc.x * p(0, 3), a01 = p(1, 0) - ndc.x * p(1, 3);
    const double a10 = p(0, 1) - ndc.y * p(0, 3), a11 = p(1, 1) - ndc.y * p(1, 3);
    const double r0 = ndc.x * w_const + p(2, 0) - p(3, 0);
    const double r1 = ndc.y * w_const + p(2, 1) - p(3, 1);
    const double det = a00 * a11 - a01 * a10;
    return {(r0 * a11 - a01 * r1) / det, (a00 * r1 - r0 * a10) / det, -1.0};
}

}  // namespace raster
