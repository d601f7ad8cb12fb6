// raster's model matrix: a scene's transform steps composed in float, each step built by transform.h.
#pragma once

#include <glm/mat4x4.hpp>

#include "raster/scene/model_transform.h"

namespace raster {

// One step's matrix.
glm::mat4 step_matrix(const TransformStep& step);

// The steps' product S_n ... S_1 in float, one step at a time (each on the left of the product so far).
glm::mat4 compose_steps(const std::vector<TransformStep>& steps);

// The mesh's model matrix: compose_steps(steps), preceded by the float inverse of compose_steps(then_inverse_of)
// when that chain is not empty.
glm::mat4 model_matrix(const ModelTransform& transform);

}  // namespace raster
