// The oracle's model matrix: a scene's transform steps composed in double from their definitions
// (docs/scene-format.md "Transforms"), sharing nothing with raster's transform code but the steps themselves.
#pragma once

#include <vector>

#include <glm/mat4x4.hpp>

#include "raster/scene/model_transform.h"

namespace raster::oracle {

// One step's matrix, exact up to double rounding: a rotation through the unit quaternion of its axis and half
// angle (the angle reduced modulo 360 degrees first), a quaternion normalised, a look-at's basis as the camera's
// (camera.h) placed at its eye.
glm::dmat4 oracle_step_matrix(const TransformStep& step);

// The rotation of unit quaternion (w, x, y, z): v -> q v q*, written out.
glm::dmat4 unit_quaternion_matrix(double w, double x, double y, double z);

// S_n ... S_1.
glm::dmat4 oracle_compose(const std::vector<TransformStep>& steps);

// inverse(C_m ... C_1) S_n ... S_1 (model_transform.h).
glm::dmat4 oracle_model_matrix(const ModelTransform& transform);

}  // namespace raster::oracle
