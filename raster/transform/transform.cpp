// Model, view, projection and viewport matrices: each written out entry by entry (GLM matrices are column-major,
// so m[col][row]).
#include "raster/transform/transform.h"

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/matrix.hpp>

namespace raster {

glm::mat4 translate_matrix(const glm::vec3& offset) {
    glm::mat4 m(1.0f);
    m[3][0] = offset.x;
    m[3][1] = offset.y;
    m[3][2] = offset.z;
    return m;
}

glm::mat4 scale_matrix(const glm::vec3& factors) {
    glm::mat4 m(1.0f);
    m[0][0] = factors.x;
    m[1][1] = factors.y;
    m[2][2] = factors.z;
    return m;
}

glm::mat4 rotate_matrix(float degrees, const glm::vec3& axis) {
    // Rodrigues' rotation formula, R = cI + s[k]x + (1 - c) k k^T, computed in double for accuracy.
    const double radians = static_cast<double>(degrees) * (M_PI / 180.0);
    const double length = std::sqrt(double(axis.x) * axis.x + double(axis.y) * axis.y + double(axis.z) * axis.z);
    const double kx = axis.x / length, ky = axis.y / length, kz = axis.z / length;
    const double c = std::cos(radians), s = std::sin(radians), t = 1.0 - c;
    glm::mat4 m(1.0f);
    m[0][0] = float(t * kx * kx + c);
    m[1][0] = float(t * kx * ky - s * kz);
    m[2][0] = float(t * kx * kz + s * ky);
    m[0][1] = float(t * kx * ky + s * kz);
    m[1][1] = float(t * ky * ky + c);
    m[2][1] = float(t * ky * kz - s * kx);
    m[0][2] = float(t * kx * kz - s * ky);
    m[1][2] = float(t * ky * kz + s * kx);
    m[2][2] = float(t * kz * kz + c);
    return m;
}

glm::mat4 quaternion_matrix(float w, float x, float y, float z) {
    return glm::mat4_cast(glm::normalize(glm::quat(w, x, y, z)));
}

namespace {

// The camera basis: u (right), v (up), w (backwards, away from the target).
struct CameraBasis {
    glm::vec3 u, v, w;
};

CameraBasis camera_basis(const glm::vec3& eye, const glm::vec3& target, const glm::vec3& up) {
    CameraBasis basis;
    basis.w = glm::normalize(eye - target);
    basis.u = glm::normalize(glm::cross(up, basis.w));
    basis.v = glm::cross(basis.w, basis.u);
    return basis;
}

}  // namespace

glm::mat4 look_at_matrix(const glm::vec3& eye, const glm::vec3& target, const glm::vec3& up) {
    const CameraBasis b = camera_basis(eye, target, up);
    glm::mat4 m(1.0f);
    // Rows are the basis vectors; the translation moves the eye to the origin.
    m[0][0] = b.u.x; m[1][0] = b.u.y; m[2][0] = b.u.z; m[3][0] = -glm::dot(b.u, eye);
    m[0][1] = b.v.x; m[1][1] = b.v.y; m[2][1] = b.v.z; m[3][1] = -glm::dot(b.v, eye);
    m[0][2] = b.w.x; m[1][2] = b.w.y; m[2][2] = b.w.z; m[3][2] = -glm::dot(b.w, eye);
    return m;
}

glm::mat4 look_at_model_matrix(const glm::vec3& eye, const glm::vec3& target, const glm::vec3& up) {
    const CameraBasis b = camera_basis(eye, target, up);
    glm::mat4 m(1.0f);
    m[0] = glm::vec4(b.u, 0.0f);
    m[1] = glm::vec4(b.v, 0.0f);
    m[2] = glm::vec4(b.w, 0.0f);
    m[3] = glm::vec4(eye, 1.0f);
    return m;
}

glm::mat4 perspective_matrix(float fov_y_degrees, float aspect, float near, float far) {
    const double half = static_cast<double>(fov_y_degrees) * (M_PI / 360.0);
    const double focal = 1.0 / std::tan(half);
    // Reversed-Z: z_clip = A * z_view + B with w_clip = -z_view, so z/w = -A + B / w_view.
    // d(near) = 1 and d(far) = 0 give B = near * far / (far - near) and -A = -near / (far - near).
    const double n = near, f = far;
    glm::mat4 m(0.0f);
    m[0][0] = float(focal / aspect);
    m[1][1] = float(focal);
    m[2][2] = float(n / (f - n));
    m[3][2] = float(n * f / (f - n));
    m[2][3] = -1.0f;
    return m;
}

glm::mat4 orthographic_matrix(float height, float aspect, float near, float far) {
    // Reversed-Z: z_clip = A * z_view + B with w_clip = 1; d(near) = 1 and d(far) = 0 (z_view = -near, -far)
    // give A = 1 / (far - near) and B = far / (far - near).
    const double h = height, n = near, f = far;
    glm::mat4 m(0.0f);
    m[0][0] = float(2.0 / (h * double(aspect)));
    m[1][1] = float(2.0 / h);
    m[2][2] = float(1.0 / (f - n));
    m[3][2] = float(f / (f - n));
    m[3][3] = 1.0f;
    return m;
}

glm::mat4 viewport_matrix(int width, int height) {
    glm::mat4 m(1.0f);
    m[0][0] = 0.5f * float(width);
    m[3][0] = 0.5f * float(width);
    m[1][1] = -0.5f * float(height);
    m[3][1] = 0.5f * float(height);
    return m;
}

glm::mat3 normal_matrix(const glm::mat4& model) {
    return glm::transpose(glm::inverse(glm::mat3(model)));
}

}  // namespace raster
