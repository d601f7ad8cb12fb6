// Model, view, projection and viewport matrices, built by hand (GLM only for vector types and quaternions).
#pragma once

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace raster {

// Affine building blocks for model transforms. Angles are in degrees; the axis need not be unit length but must
// be non-zero (callers validate). The quaternion is (w, x, y, z) and is normalised here.
glm::mat4 translate_matrix(const glm::vec3& offset);
glm::mat4 scale_matrix(const glm::vec3& factors);
glm::mat4 rotate_matrix(float degrees, const glm::vec3& axis);
glm::mat4 quaternion_matrix(float w, float x, float y, float z);

// World-to-view matrix of a camera at `eye` looking at `target` with `up` (right-handed, looking down -z).
// Callers guarantee eye != target and up not parallel to the view direction.
glm::mat4 look_at_matrix(const glm::vec3& eye, const glm::vec3& target, const glm::vec3& up);

// The inverse of look_at_matrix: places an object at `eye`, its -z axis towards `target` (the `lookat` step of a
// model transform chain).
glm::mat4 look_at_model_matrix(const glm::vec3& eye, const glm::vec3& target, const glm::vec3& up);

// Perspective projection to clip space with reversed-Z depth (see conventions.h): a point at view depth `near`
// gets z/w = 1, at `far` z/w = 0. fov_y is the full vertical field of view in degrees; aspect = width / height.
glm::mat4 perspective_matrix(float fov_y_degrees, float aspect, float near, float far);

// Orthographic projection with reversed-Z depth and w = 1: a view volume `height` high and height * aspect wide
// maps to x, y in [-1, 1]; a point at view depth `near` gets z = 1, at `far` z = 0.
glm::mat4 orthographic_matrix(float height, float aspect, float near, float far);

// Maps NDC x, y in [-1, 1] (y up) to screen pixels (y down): (-1, 1) -> (0, 0), (1, -1) -> (width, height).
// Depth passes through unchanged.
glm::mat4 viewport_matrix(int width, int height);

// The matrix that transforms normals: the inverse-transpose of the upper 3x3 of `model`.
glm::mat3 normal_matrix(const glm::mat4& model);

}  // namespace raster
