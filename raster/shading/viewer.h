// Where lit points are seen from: the camera's eye, or, for an orthographic camera, one direction for every point.
#pragma once

#include <glm/vec3.hpp>

#include "raster/scene/scene.h"

namespace raster {

// Lighting's view vector (docs/conventions.md "Lighting"): from a point towards the eye for a perspective camera;
// for an orthographic one every view ray is parallel, and the view vector is the camera's back direction,
// normalize(eye - target), at every point.
struct Viewer {
    glm::vec3 eye{0.0f};
    bool parallel = false;
    glm::vec3 back{0.0f, 0.0f, 1.0f};  // unit; used when parallel
};

Viewer viewer_of(const Camera& camera);

// The unit view vector at `position` (zero at the eye itself).
glm::vec3 to_viewer(const Viewer& viewer, const glm::vec3& position);

}  // namespace raster
