// The float camera's error bounds; the derivations are next to the declarations in camera_precision.h.
#include "oracle/reference/camera_precision.h"

#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

#include "oracle/reference/precision.h"

namespace raster::oracle {

CameraMatrixError raster_camera_error(const Camera& camera, const OracleCamera& exact) {
    CameraMatrixError error;
    const double e_back = float_gamma(kViewBackRoundings);
    const double g2 = float_gamma(kCrossRoundings), g5 = float_gamma(kNormalizeRoundings), g3 = float_gamma(3);
    const glm::dvec3 up(camera.up);
    const double sin_theta = glm::length(glm::cross(up, exact.back)) / glm::length(up);
    double e_right = 2.0 * (e_back + 2.0 * g2 * (1.0 + e_back)) / sin_theta + g5;
    if (!(e_right < 2.0)) e_right = std::numeric_limits<double>::infinity();  // no direction is certain
    const double e_up = e_back + e_right + e_back * e_right + 2.0 * g2 * (1.0 + e_back) * (1.0 + e_right);
    error.row = {e_right, e_up, e_back};
    const double eye = glm::length(exact.eye);
    for (int i = 0; i < 3; ++i) error.translation[i] = error.row[i] * eye + g3 * (1.0 + error.row[i]) * eye;
    error.projection = float_gamma(kProjectionRoundings);
    return error;
}

glm::dvec4 camera_clip_error(const CameraMatrixError& error, const OracleCamera& exact, const glm::dvec3& world) {
    const glm::dvec3 view = view_of_world(exact, world);
    const double q = glm::length(world);
    const glm::dvec3 e = error.row * q + error.translation;  // view-space error per row
    const glm::dvec3 reach = glm::abs(view) + e;
    const glm::dmat4& p = exact.projection;
    // |P| applied to a view-space vector (x, y, z, 0): P has only the entries 00, 11, 22, 32 and 23 (perspective)
    // or 33 (orthographic: an exact 1, so w has no error).
    auto through_p = [&](const glm::dvec3& v) {
        return glm::dvec4(std::fabs(p[0][0]) * v.x, std::fabs(p[1][1]) * v.y, std::fabs(p[2][2]) * v.z,
                          std::fabs(p[2][3]) * v.z);
    };
    glm::dvec4 clip = error.projection * through_p(reach) + through_p(e);
    clip.z += error.projection * std::fabs(p[3][2]);  // the depth row's constant, times the homogeneous 1
    return clip;
}

}  // namespace raster::oracle
