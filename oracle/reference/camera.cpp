// The oracle's camera: the basis, projection and viewport mapping, in double.
#include "oracle/reference/camera.h"

#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

namespace raster::oracle {

OracleCamera oracle_camera(const Camera& camera, int width, int height) {
    OracleCamera c;
    c.eye = glm::dvec3(camera.eye);
    c.back = glm::normalize(glm::dvec3(camera.eye) - glm::dvec3(camera.target));
    c.right = glm::normalize(glm::cross(glm::dvec3(camera.up), c.back));
    c.up = glm::cross(c.back, c.right);
    c.focal = 1.0 / std::tan(static_cast<double>(camera.fov_y_degrees) * std::numbers::pi / 360.0);
    c.aspect = static_cast<double>(width) / static_cast<double>(height);
    c.near = camera.near;
    c.far = camera.far;
    c.width = width;
    c.height = height;
    const glm::dvec3 rows[3] = {c.right, c.up, c.back};
    for (int r = 0; r < 3; ++r) {
        for (int k = 0; k < 3; ++k) c.view[k][r] = rows[r][k];  // glm is column-major: m[column][row]
        c.view[3][r] = -glm::dot(rows[r], c.eye);
    }
    // Reversed-Z: z_clip = A z_view + B, w_clip = -z_view, so d = z/w = -A + B / t. d(near) = 1 and d(far) = 0
    // give A = near / (far - near) and B = near far / (far - near).
    const double n = c.near, f = c.far;
    c.projection = glm::dmat4(0.0);
    c.projection[0][0] = c.focal / c.aspect;
    c.projection[1][1] = c.focal;
    c.projection[2][2] = n / (f - n);
    c.projection[3][2] = n * f / (f - n);
    c.projection[2][3] = -1.0;
    return c;
}

glm::dvec3 view_of_world(const OracleCamera& camera, const glm::dvec3& world) {
    const glm::dvec3 offset = world - camera.eye;
    return {glm::dot(camera.right, offset), glm::dot(camera.up, offset), glm::dot(camera.back, offset)};
}

glm::dvec2 ndc_of_screen(const OracleCamera& camera, const glm::dvec2& screen) {
    return {2.0 * screen.x / camera.width - 1.0, 1.0 - 2.0 * screen.y / camera.height};
}

glm::dvec2 screen_of_ndc(const OracleCamera& camera, const glm::dvec2& ndc) {
    return {(ndc.x + 1.0) * 0.5 * camera.width, (1.0 - ndc.y) * 0.5 * camera.height};
}

glm::dvec3 ray_direction(const OracleCamera& camera, const glm::dvec2& screen) {
    // The view point (x, y, -1) projects to NDC (focal x / aspect, focal y).
    const glm::dvec2 ndc = ndc_of_screen(camera, screen);
    return {ndc.x * camera.aspect / camera.focal, ndc.y / camera.focal, -1.0};
}

double reversed_z(const OracleCamera& camera, double view_depth) {
    const double n = camera.near, f = camera.far;
    return n * (f - view_depth) / (view_depth * (f - n));
}

}  // namespace raster::oracle
