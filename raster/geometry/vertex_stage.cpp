// Vertex stage: transforms positions to clip space and, only when shading needs them, to world space with
// normals by the inverse-transpose.
#include "raster/geometry/vertex_stage.h"

#include <glm/geometric.hpp>

#include "raster/core/unit_vector.h"
#include "raster/transform/model_matrix.h"
#include "raster/transform/transform.h"

namespace raster {

VertexStageNeeds vertex_stage_needs(ShadingMode mode) {
    VertexStageNeeds needs;
    needs.world_positions = mode != ShadingMode::unlit;
    needs.vertex_normals = mode == ShadingMode::gouraud || mode == ShadingMode::phong ||
                           mode == ShadingMode::blinn_phong || mode == ShadingMode::cel || mode == ShadingMode::gooch;
    return needs;
}

namespace {

// Unit normal of each vertex: the normalised sum of the unit normals of the faces around it.
void average_face_normals(const std::vector<glm::vec3>& world, const std::vector<TriangleIndices>& triangles,
                          uint32_t first_vertex, uint32_t vertex_count, std::vector<glm::vec3>& normals) {
    for (const auto& tri : triangles) {
        const glm::vec3& a = world[first_vertex + tri.v[0]];
        const glm::vec3& b = world[first_vertex + tri.v[1]];
        const glm::vec3& c = world[first_vertex + tri.v[2]];
        const glm::vec3 n = unit_or_zero(glm::cross(b - a, c - a));  // of a face of any size (unit_vector.h)
        if (n == glm::vec3(0.0f)) continue;  // degenerate faces have no direction to contribute
        for (uint32_t corner : tri.v) normals[first_vertex + corner] += n;
    }
    for (uint32_t i = 0; i < vertex_count; ++i) normals[first_vertex + i] = unit_or_zero(normals[first_vertex + i]);
}

}  // namespace

TransformedScene run_vertex_stage(const Scene& scene, const VertexStageNeeds& needs) {
    return run_vertex_stage(scene, needs, view_matrix(scene.camera),
                            projection_matrix(scene.camera, scene.settings.width, scene.settings.height));
}

TransformedScene run_vertex_stage(const Scene& scene, const VertexStageNeeds& needs, const glm::mat4& view,
                                  const glm::mat4& projection) {
    TransformedScene out;
    out.view = view;
    out.projection = projection;
    const glm::mat4 view_projection = out.projection * out.view;

    size_t vertex_total = 0, triangle_total = 0;
    for (const auto& mesh : scene.meshes) {
        vertex_total += mesh.data->positions.size();
        triangle_total += mesh.data->triangles.size();
    }
    out.clip.reserve(vertex_total);
    out.triangles.reserve(triangle_total);
    out.triangle_mesh.reserve(triangle_total);
    if (needs.world_positions || needs.vertex_normals) out.world_position.reserve(vertex_total);
    if (needs.vertex_normals) out.world_normal.assign(vertex_total, glm::vec3(0.0f));

    for (uint32_t mesh_index = 0; mesh_index < scene.meshes.size(); ++mesh_index) {
        const SceneMesh& mesh = scene.meshes[mesh_index];
        const uint32_t first_vertex = static_cast<uint32_t>(out.clip.size());
        out.mesh_first_vertex.push_back(first_vertex);
        out.mesh_first_triangle.push_back(static_cast<uint32_t>(out.triangles.size()));
        const glm::mat4 model = model_matrix(mesh.transform);
        const glm::mat4 model_view_projection = view_projection * model;
        for (const glm::vec3& p : mesh.data->positions) {
            out.clip.push_back(model_view_projection * glm::vec4(p, 1.0f));
            if (needs.world_positions || needs.vertex_normals)
                out.world_position.push_back(glm::vec3(model * glm::vec4(p, 1.0f)));
        }
        for (const TriangleIndices& tri : mesh.data->triangles) {
            out.triangles.push_back({{first_vertex + tri.v[0], first_vertex + tri.v[1], first_vertex + tri.v[2]}});
            out.triangle_mesh.push_back(mesh_index);
        }
        if (!needs.vertex_normals) continue;
        const auto vertex_count = static_cast<uint32_t>(mesh.data->positions.size());
        if (mesh.data->normals.size() == mesh.data->positions.size()) {
            const glm::mat3 to_world = normal_matrix(model);
            for (uint32_t i = 0; i < vertex_count; ++i)
                out.world_normal[first_vertex + i] = unit_or_zero(to_world * mesh.data->normals[i]);
        } else {
            average_face_normals(out.world_position, mesh.data->triangles, first_vertex, vertex_count,
                                 out.world_normal);
        }
    }
    return out;
}

}  // namespace raster
