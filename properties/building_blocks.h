// The building blocks that the properties do not take through StageFunctions (matrix builders, the loader's
// transform chain, keyframe sampling), as replaceable functions with the real ones as defaults, so checks can take them as parameters.
#pragma once

#include <array>
#include <string>

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "raster/scene/animation.h"
#include "raster/transform/transform.h"

namespace raster::properties {

// A mesh transform chain as a scene file lists it: `scale`, then `rotate`, then `translate` (docs/scene-format.md).
struct ScaleRotateTranslate {
    glm::vec3 scale{1.0f};
    float degrees = 0.0f;
    glm::vec3 axis{0.0f, 0.0f, 1.0f};
    glm::vec3 offset{0.0f};
};

// A float as a scene file writes it, nine significant digits, so that it reads back exactly; a vector likewise.
std::string yaml_number(float value);
std::string yaml_vector(const glm::vec3& v);

// A raster scene file: `preamble` (image, camera, render settings), then one mesh of one triangle listing the
// chain's three steps as its transform, every float printed so that it reads back exactly.
std::string scene_file_with_chain(const ScaleRotateTranslate& chain, const std::array<glm::vec3, 3>& triangle,
                                  const std::string& preamble = "");

// The model matrix the scene loader builds for that chain: parse_scene's model matrix of that file.
glm::mat4 model_matrix_from_scene_file(const ScaleRotateTranslate& chain);

// Each block is a plain function pointer to the production builder, which the matrix properties call; a bug of the
// catalogue is planted into the builder's source (mutants/bugs.txt), so the vertex stage, which calls the same
// builders, runs it too.
struct BuildingBlocks {
    glm::mat4 (*look_at)(const glm::vec3& eye, const glm::vec3& target, const glm::vec3& up) = look_at_matrix;
    glm::mat4 (*look_at_inverse)(const glm::vec3& eye, const glm::vec3& target, const glm::vec3& up) =
        look_at_model_matrix;
    glm::mat4 (*perspective)(float fov_y_degrees, float aspect, float near, float far) = perspective_matrix;
    glm::mat4 (*orthographic)(float height, float aspect, float near, float far) = orthographic_matrix;
    glm::mat4 (*viewport)(int width, int height) = viewport_matrix;
    glm::mat3 (*normal_matrix)(const glm::mat4& model) = raster::normal_matrix;
    glm::mat4 (*model_matrix)(const ScaleRotateTranslate& chain) = model_matrix_from_scene_file;
    // Keyframe sampling (raster/scene/animation.h), which the animation properties call.
    glm::vec4 (*slerp)(const glm::vec4& a, const glm::vec4& b, float t) = raster::slerp;
    glm::vec3 (*sample_positions)(const Track<glm::vec3>& track, float time) = raster::sample_track;
    glm::vec4 (*sample_rotations)(const Track<glm::vec4>& track, float time) = raster::sample_track;
};

}  // namespace raster::properties
