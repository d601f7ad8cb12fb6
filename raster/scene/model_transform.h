// A mesh's model transform as its file gives it: the steps, kept as written, that raster and the oracle each compose.
#pragma once

#include <variant>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace raster {

struct TranslateStep {
    glm::vec3 offset{0.0f};
};
struct ScaleStep {
    glm::vec3 factors{1.0f};
};
// Right-handed: a positive angle turns counter-clockwise seen from the tip of the axis; the axis is any non-zero
// vector (its direction is what counts).
struct RotateStep {
    float degrees = 0.0f;
    glm::vec3 axis{0.0f, 0.0f, 1.0f};
};
// The rotation of the quaternion w + x i + y j + z k, normalised first; never zero.
struct QuaternionStep {
    glm::vec4 wxyz{1.0f, 0.0f, 0.0f, 0.0f};
};
// Places the object at `eye` with its -z axis towards `target` and its y axis in the plane of `up` (the inverse of a
// camera's view with the same eye, target and up).
struct LookAtStep {
    glm::vec3 eye{0.0f}, target{0.0f, 0.0f, -1.0f}, up{0.0f, 1.0f, 0.0f};
};
// A matrix written out by the format (column-major: matrix[column][row]).
struct MatrixStep {
    glm::mat4 matrix{1.0f};
};
using TransformStep = std::variant<TranslateStep, ScaleStep, RotateStep, QuaternionStep, LookAtStep, MatrixStep>;

// model = inverse(C_m ... C_1) S_n ... S_1: the steps apply to the object first to last; `then_inverse_of`, when
// not empty, is a chain whose inverse follows them (seed 001 folds its camera's camera-to-world chain into every
// object this way). No steps is the identity.
struct ModelTransform {
    std::vector<TransformStep> steps;
    std::vector<TransformStep> then_inverse_of;
};

// A bound on the largest row sum of |M| for the steps' product (each step's own bound multiplied), so a scene whose
// matrix could leave float's range is refused before anything composes it (validation.h).
double model_magnitude_bound(const std::vector<TransformStep>& steps);
inline constexpr double kMaxModelMagnitude = 1e30;

}  // namespace raster
