// The view vector of perspective and orthographic cameras.
#include "raster/shading/viewer.h"

#include "raster/core/unit_vector.h"

namespace raster {

Viewer viewer_of(const Camera& camera) {
    Viewer viewer;
    viewer.eye = camera.eye;
    viewer.parallel = camera.projection == Projection::orthographic;
    viewer.back = unit_or_zero(camera.eye - camera.target);
    return viewer;
}

glm::vec3 to_viewer(const Viewer& viewer, const glm::vec3& position) {
    return viewer.parallel ? viewer.back : unit_or_zero(viewer.eye - position);
}

}  // namespace raster
