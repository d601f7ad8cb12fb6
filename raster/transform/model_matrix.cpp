// raster's model matrix, composed in float from the scene's transform steps.
#include "raster/transform/model_matrix.h"

#include <type_traits>

#include <glm/matrix.hpp>

#include "raster/transform/transform.h"

namespace raster {

glm::mat4 step_matrix(const TransformStep& step) {
    return std::visit(
        [](const auto& s) -> glm::mat4 {
            using Step = std::decay_t<decltype(s)>;
            if constexpr (std::is_same_v<Step, TranslateStep>) return translate_matrix(s.offset);
            else if constexpr (std::is_same_v<Step, ScaleStep>) return scale_matrix(s.factors);
            else if constexpr (std::is_same_v<Step, RotateStep>) return rotate_matrix(s.degrees, s.axis);
            else if constexpr (std::is_same_v<Step, QuaternionStep>)
                return quaternion_matrix(s.wxyz[0], s.wxyz[1], s.wxyz[2], s.wxyz[3]);
            else if constexpr (std::is_same_v<Step, LookAtStep>) return look_at_model_matrix(s.eye, s.target, s.up);
            else return s.matrix;
        },
        step);
}

glm::mat4 compose_steps(const std::vector<TransformStep>& steps) {
    glm::mat4 product(1.0f);
    for (const TransformStep& step : steps) product = step_matrix(step) * product;
    return product;
}

glm::mat4 model_matrix(const ModelTransform& transform) {
    const glm::mat4 model = compose_steps(transform.steps);
    if (transform.then_inverse_of.empty()) return model;
    return glm::inverse(compose_steps(transform.then_inverse_of)) * model;
}

}  // namespace raster
