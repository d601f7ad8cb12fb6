// A camera's view and projection matrices.
#include "raster/transform/camera_matrices.h"

#include "raster/transform/transform.h"

namespace raster {

glm::mat4 view_matrix(const Camera& camera) { return look_at_matrix(camera.eye, camera.target, camera.up); }

glm::mat4 projection_matrix(const Camera& camera, int width, int height) {
    const float aspect = static_cast<float>(width) / static_cast<float>(height);
    if (camera.projection == Projection::orthographic)
        return orthographic_matrix(camera.ortho_height, aspect, camera.near, camera.far);
    return perspective_matrix(camera.fov_y_degrees, aspect, camera.near, camera.far);
}

}  // namespace raster
