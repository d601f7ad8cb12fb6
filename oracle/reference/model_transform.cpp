// The oracle's model matrix, step by step in double.
#include "oracle/reference/model_transform.h"

#include <cmath>
#include <numbers>
#include <type_traits>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "oracle/reference/camera.h"

namespace raster::oracle {

glm::dmat4 unit_quaternion_matrix(double w, double x, double y, double z) {
    glm::dmat4 m(1.0);
    m[0][0] = w * w + x * x - y * y - z * z;
    m[1][1] = w * w - x * x + y * y - z * z;
    m[2][2] = w * w - x * x - y * y + z * z;
    m[1][0] = 2.0 * (x * y - w * z);  // row 0, column 1
    m[0][1] = 2.0 * (x * y + w * z);
    m[2][0] = 2.0 * (x * z + w * y);
    m[0][2] = 2.0 * (x * z - w * y);
    m[2][1] = 2.0 * (y * z - w * x);
    m[1][2] = 2.0 * (y * z + w * x);
    return m;
}

glm::dmat4 oracle_step_matrix(const TransformStep& step) {
    return std::visit(
        [](const auto& s) -> glm::dmat4 {
            using Step = std::decay_t<decltype(s)>;
            glm::dmat4 m(1.0);
            if constexpr (std::is_same_v<Step, TranslateStep>) {
                m[3] = glm::dvec4(glm::dvec3(s.offset), 1.0);
            } else if constexpr (std::is_same_v<Step, ScaleStep>) {
                for (int i = 0; i < 3; ++i) m[i][i] = s.factors[i];
            } else if constexpr (std::is_same_v<Step, RotateStep>) {
                // Right-handed about the unit axis k: the quaternion (cos(a/2), sin(a/2) k).
                const double half = std::fmod(double(s.degrees), 360.0) * std::numbers::pi / 360.0;
                const glm::dvec3 k = glm::normalize(glm::dvec3(s.axis)) * std::sin(half);
                m = unit_quaternion_matrix(std::cos(half), k.x, k.y, k.z);
            } else if constexpr (std::is_same_v<Step, QuaternionStep>) {
                const glm::dvec4 q = glm::dvec4(s.wxyz) / glm::length(glm::dvec4(s.wxyz));
                m = unit_quaternion_matrix(q[0], q[1], q[2], q[3]);
            } else if constexpr (std::is_same_v<Step, LookAtStep>) {
                // The object's axes are the camera basis of the same eye, target and up: x right, y up, z back.
                const OracleCamera basis = oracle_camera(look_at_camera(s), 1, 1);
                m[0] = glm::dvec4(basis.right, 0.0);
                m[1] = glm::dvec4(basis.up, 0.0);
                m[2] = glm::dvec4(basis.back, 0.0);
                m[3] = glm::dvec4(basis.eye, 1.0);
            } else {
                m = glm::dmat4(s.matrix);
            }
            return m;
        },
        step);
}

glm::dmat4 oracle_compose(const std::vector<TransformStep>& steps) {
    glm::dmat4 product(1.0);
    for (const TransformStep& step : steps) product = oracle_step_matrix(step) * product;
    return product;
}

glm::dmat4 oracle_model_matrix(const ModelTransform& transform) {
    const glm::dmat4 model = oracle_compose(transform.steps);
    if (transform.then_inverse_of.empty()) return model;
    return glm::inverse(oracle_compose(transform.then_inverse_of)) * model;
}

}  // namespace raster::oracle
