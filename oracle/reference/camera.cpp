// The oracle's camera: the basis, projection and viewport mapping, in double.
#include "oracle/reference/camera.h"

#include <cmath>
#include <limits>
#include <numbers>

#include <glm/geometric.hpp>

namespace raster::oracle {

OracleCamera oracle_camera(const Camera& camera, int width, int height) {
    OracleCamera c;
    c.eye = glm::dvec3(camera.eye);
    c.back = glm::normalize(glm::dvec3(camera.eye) - glm::dvec3(camera.target));
    c.right = glm::normalize(glm::cross(glm::dvec3(camera.up), c.back));
    c.up = glm::cross(c.back, c.right);
    c.orthographic = camera.projection == Projection::orthographic;
    c.focal = 1.0 / std::tan(static_cast<double>(camera.fov_y_degrees) * std::numbers::pi / 360.0);
    c.half_height = 0.5 * static_cast<double>(camera.ortho_height);
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
    const double n = c.near, f = c.far;
    c.projection = glm::dmat4(0.0);
    if (c.orthographic) {
        // Reversed-Z with w = 1: d = z = A z_view + B = (f - t) / (f - n), 1 at t = near and 0 at t = far.
        c.projection[0][0] = 1.0 / (c.half_height * c.aspect);
        c.projection[1][1] = 1.0 / c.half_height;
        c.projection[2][2] = 1.0 / (f - n);
        c.projection[3][2] = f / (f - n);
        c.projection[3][3] = 1.0;
        return c;
    }
    // Reversed-Z: z_clip = A z_view + B, w_clip = -z_view, so d = z/w = -A + B / t. d(near) = 1 and d(far) = 0
    // give A = near / (far - near) and B = near far / (far - near).
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

glm::dvec3 ray_origin(const OracleCamera& camera, const glm::dvec2& screen) {
    if (!camera.orthographic) return glm::dvec3(0.0);
    // The view point (x, y, z) projects to NDC (x / (half_height aspect), y / half_height) at every z.
    const glm::dvec2 ndc = ndc_of_screen(camera, screen);
    return {ndc.x * camera.half_height * camera.aspect, ndc.y * camera.half_height, 0.0};
}

glm::dvec3 ray_direction(const OracleCamera& camera, const glm::dvec2& screen) {
    if (camera.orthographic) return {0.0, 0.0, -1.0};
    // The view point (x, y, -1) projects to NDC (focal x / aspect, focal y).
    const glm::dvec2 ndc = ndc_of_screen(camera, screen);
    return {ndc.x * camera.aspect / camera.focal, ndc.y / camera.focal, -1.0};
}

bool faces_viewer(const OracleCamera& camera, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    const glm::dvec3 normal = glm::cross(b - a, c - a);
    return camera.orthographic ? normal.z > 0.0 : glm::dot(normal, a) < 0.0;
}

double reversed_z(const OracleCamera& camera, double view_depth) {
    const double n = camera.near, f = camera.far;
    if (camera.orthographic) return (f - view_depth) / (f - n);
    return n * (f - view_depth) / (view_depth * (f - n));
}

double reversed_z_error_of_view_depth(const OracleCamera& camera, double view_depth, double error) {
    if (camera.orthographic) return error / (camera.far - camera.near);
    // d = -A + B / t with B = projection[3][2]: |B / t' - B / t| for |t' - t| <= error < t.
    if (!(error < view_depth)) return std::numeric_limits<double>::infinity();
    return std::fabs(camera.projection[3][2]) * error / (view_depth * (view_depth - error));
}

}  // namespace raster::oracle
