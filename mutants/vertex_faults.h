// The vertex stage's and the matrix building blocks' faulty variants of the bug catalogue, with the signatures of
// PipelineStages::vertex and of the BuildingBlocks they replace; vertex_faults.cpp describes each bug where it is
// written.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "mutants/building_blocks.h"
#include "raster/pipeline/vertex_stage.h"
#include "raster/scene/scene.h"

namespace raster::mutants {

// "integer-divided aspect ratio"
TransformedScene vertex_with_integer_aspect(const Scene& scene, const VertexStageNeeds& needs);

// "normals not transformed by the inverse-transpose"
TransformedScene vertex_with_model_matrix_normals(const Scene& scene, const VertexStageNeeds& needs);

// "look-at basis not orthonormal": the faulty block, and the vertex stage that builds its view matrix with it.
glm::mat4 look_at_with_raw_up(const glm::vec3& eye, const glm::vec3& target, const glm::vec3& up);
TransformedScene vertex_with_raw_up(const Scene& scene, const VertexStageNeeds& needs);

// "OpenGL [-1, 1] depth mapping": the faulty block, and the vertex stage that projects with it.
glm::mat4 perspective_with_opengl_depth(float fov_y_degrees, float aspect, float near, float far);
TransformedScene vertex_with_opengl_depth(const Scene& scene, const VertexStageNeeds& needs);

// "model matrix multiplied in the wrong order"
glm::mat4 model_matrix_composed_backwards(const ScaleRotateTranslate& chain);

}  // namespace raster::mutants
