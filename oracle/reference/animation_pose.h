// The oracle's pose of an animated mesh: its node chain at the scene's instant, every track sampled in double by
// the oracle's own interpolation (docs/animation.md: step, linear with slerp the short way, glTF's cubic spline),
// with the bound on how far raster's float sampling and composition can be from it. raster's posed transform steps
// are not read: a sampling bug of raster's shows as geometry the oracle does not expect.
#pragma once

#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "oracle/reference/model_precision.h"
#include "raster/scene/animation.h"

namespace raster::oracle {

// A track's value at `time` in double, and the bound on raster's float value, per component (positions) or as the
// distance between unit quaternions in R^4, taken with the sign that faces the oracle's (rotations).
struct SampledVector {
    glm::dvec3 value{0.0};
    glm::dvec3 bound{0.0};
};
struct SampledRotation {
    glm::dvec4 wxyz{1.0, 0.0, 0.0, 0.0};  // unit
    double bound = 0.0;
};
SampledVector oracle_sample(const Track<glm::vec3>& track, float time);
SampledRotation oracle_sample(const Track<glm::vec4>& track, float time);

// The unit quaternion a fraction t along the shorter arc from unit a to unit b, at a constant rate: a cos(t w) +
// n sin(t w), n the unit direction of b's part orthogonal to a (b negated first when a . b < 0), w the arc.
glm::dvec4 oracle_slerp(const glm::dvec4& a, const glm::dvec4& b, double t);

// Mesh `mesh`'s model matrix at `time` (its placement's own steps, then its node's chain to the root, each node's
// fixed steps, scale, rotation and translation) and raster's bound; null-placed meshes are not animated.
ModelMatrixError posed_model_error(const SceneAnimation& animation, size_t mesh, float time);

}  // namespace raster::oracle
