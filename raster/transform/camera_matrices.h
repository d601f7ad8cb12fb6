// A camera's view and projection matrices: what the scene's Camera means, as transform.h builds them.
#pragma once

#include <glm/mat4x4.hpp>

#include "raster/scene/scene.h"

namespace raster {

// World to view: the camera at the origin looking down -z with y up (look_at_matrix).
glm::mat4 view_matrix(const Camera& camera);

// View to clip space for an image of width x height pixels (aspect = width / height), reversed-Z
// (perspective_matrix or orthographic_matrix by the camera's projection; conventions.h).
glm::mat4 projection_matrix(const Camera& camera, int width, int height);

}  // namespace raster
