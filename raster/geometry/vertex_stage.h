// Vertex stage: scene meshes -> one flat list of triangles with clip-space positions, plus the world-space
// attributes that the chosen shading needs (and nothing else).
#pragma once

#include <cstdint>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "raster/transform/camera_matrices.h"
#include "raster/scene/scene.h"

namespace raster {

// Output of the vertex stage, read by clipping (clip positions) and by shading (the rest).
// Vertex indices are global: mesh k's vertex i is vertex mesh_first_vertex[k] + i.
// Triangle ids are global too: the scene's triangles in mesh order; they survive clipping unchanged.
struct TransformedScene {
    glm::mat4 view{1.0f};
    glm::mat4 projection{1.0f};
    std::vector<TriangleIndices> triangles;   // global vertex indices
    std::vector<uint32_t> triangle_mesh;      // mesh index of each triangle
    std::vector<uint32_t> mesh_first_vertex;  // per mesh
    std::vector<uint32_t> mesh_first_triangle;  // per mesh
    std::vector<glm::vec4> clip;              // per vertex: projection * view * model * position
    std::vector<glm::vec3> world_position;    // per vertex; only for lit shading modes
    std::vector<glm::vec3> world_normal;      // per vertex, unit; only for gouraud, phong and blinn-phong
};

// What the vertex stage must compute; derived from the shading mode.
struct VertexStageNeeds {
    bool world_positions = false;
    bool vertex_normals = false;
};
VertexStageNeeds vertex_stage_needs(ShadingMode mode);

// Runs the vertex stage. Normals come from the mesh (transformed by the inverse-transpose of the model matrix)
// or, when the mesh has none, from averaging the unit normals of the adjacent faces in world space.
TransformedScene run_vertex_stage(const Scene& scene, const VertexStageNeeds& needs);

// The same with explicit view and projection matrices (the camera's are view_matrix and projection_matrix).
TransformedScene run_vertex_stage(const Scene& scene, const VertexStageNeeds& needs, const glm::mat4& view,
                                  const glm::mat4& projection);

}  // namespace raster
