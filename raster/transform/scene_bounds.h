// The box that bounds a scene in world space: what a default camera frames and what an open far plane must reach.
#pragma once

#include <optional>

#include <glm/vec3.hpp>

#include "raster/scene/scene.h"

namespace raster {

// A box and the sphere about its centre through the farthest point that made it, in double (a float sum or length
// of coordinates near float's limit would overflow).
struct WorldBounds {
    glm::dvec3 lo{0.0}, hi{0.0};
    glm::dvec3 centre{0.0};
    double radius = 0.0;
};

// The bounds of every triangle's vertices (vertices no triangle uses do not count) placed by their mesh's model
// matrix (model_matrix.h); none when the scene has no triangles.
std::optional<WorldBounds> world_bounds(const Scene& scene);

}  // namespace raster
