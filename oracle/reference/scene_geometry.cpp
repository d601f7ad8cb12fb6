// The oracle's scene geometry: positions, views and normals in double, and raster's attribute error bounds.
#include "oracle/reference/scene_geometry.h"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "oracle/reference/animation_pose.h"
#include "oracle/reference/shading_precision.h"

namespace raster::oracle {
namespace {

glm::dvec3 unit_or_zero(const glm::dvec3& v) {
    const double length = glm::length(v);
    return length > 0.0 ? v / length : glm::dvec3(0.0);
}

bool needs_world(ShadingMode mode) { return mode != ShadingMode::unlit; }
bool needs_normals(ShadingMode mode) {
    return mode == ShadingMode::gouraud || mode == ShadingMode::phong || mode == ShadingMode::blinn_phong ||
           mode == ShadingMode::cel || mode == ShadingMode::gooch;
}

// The vertex normals of one mesh and raster's error bounds for them.
void mesh_normals(const SceneMesh& mesh, const ModelMatrixError& model, uint32_t first, OracleScene& out) {
    const MeshData& data = *mesh.data;
    const size_t count = data.positions.size();
    if (data.normals.size() == count) {
        const glm::dmat3 to_world = glm::transpose(glm::inverse(glm::dmat3(model.exact)));
        const NormalMatrixError normal_matrix = raster_normal_matrix_error(model);
        for (size_t i = 0; i < count; ++i) {
            out.normal[first + i] = unit_or_zero(to_world * glm::dvec3(data.normals[i]));
            out.normal_error[first + i] = raster_file_normal_error(normal_matrix, data.normals[i]);
        }
        return;
    }
    std::vector<std::vector<TriangleIndices>> faces_of(count);
    for (const TriangleIndices& t : data.triangles) {
        const glm::dvec3 n = glm::cross(out.world[first + t.v[1]] - out.world[first + t.v[0]],
                                        out.world[first + t.v[2]] - out.world[first + t.v[0]]);
        const double length = glm::length(n);
        for (uint32_t corner : t.v) {
            faces_of[corner].push_back(t);
            if (length > 0.0) out.normal[first + corner] += n / length;
        }
    }
    for (size_t i = 0; i < count; ++i) {
        out.normal[first + i] = unit_or_zero(out.normal[first + i]);
        out.normal_error[first + i] = raster_averaged_normal_error(out.world, out.world_error, faces_of[i], first);
    }
}

}  // namespace

bool layered_material(const Material& material) {
    return !(material.opacity >= 1.0f) || (material.texture.has_value() && material.texture->reads_alpha);
}

const Material& triangle_material(const Scene& scene, const OracleTriangle& triangle) {
    const SceneMesh& mesh = scene.meshes[triangle.mesh];
    const Material* material = &mesh.material;
    for (const MaterialPart& part : mesh.parts)
        if (part.first_triangle <= triangle.local) material = &part.material;
    return *material;
}

namespace {

// A mesh an animated node carries is posed by the oracle at the scene's instant (animation_pose.h), whatever steps
// raster's posing wrote; any other mesh's transform is the file's.
ModelMatrixError model_error_of(const Scene& scene, uint32_t mesh) {
    const SceneAnimation* animation = scene.animation.get();
    if (animation && mesh < animation->meshes.size() && animation->meshes[mesh].node >= 0)
        return posed_model_error(*animation, mesh, scene.posed_at);
    return raster_model_error(scene.meshes[mesh].transform);
}

// Camera, triangles, world and view positions (and world errors when `world_errors`).
OracleScene view_of_scene(const Scene& scene, const Camera& camera, int width, int height, bool world_errors) {
    OracleScene out;
    out.camera = oracle_camera(camera, width, height);
    out.camera_error = raster_camera_error(camera, out.camera);
    for (uint32_t m = 0; m < scene.meshes.size(); ++m) {
        const SceneMesh& mesh = scene.meshes[m];
        const uint32_t first = static_cast<uint32_t>(out.world.size());
        out.mesh_first_vertex.push_back(first);
        const ModelMatrixError& model = out.models.emplace_back(model_error_of(scene, m));
        for (const glm::vec3& p : mesh.data->positions) {
            const glm::dvec3 world(model.exact * glm::dvec4(glm::dvec3(p), 1.0));
            out.world.push_back(world);
            out.view.push_back(view_of_world(out.camera, world));
            if (world_errors) out.world_error.push_back(raster_world_position_error(model, p));
        }
        for (uint32_t t = 0; t < mesh.data->triangles.size(); ++t) {
            const auto& v = mesh.data->triangles[t].v;
            out.triangles.push_back({m, t, {first + v[0], first + v[1], first + v[2]}});
        }
    }
    return out;
}

}  // namespace

OracleScene oracle_view(const Scene& scene, const Camera& camera, int width, int height) {
    return view_of_scene(scene, camera, width, height, false);
}

OracleScene oracle_scene(const Scene& scene) {
    const ShadingMode mode = scene.settings.shading;
    OracleScene out = view_of_scene(scene, scene.camera, scene.settings.width, scene.settings.height, needs_world(mode));
    if (needs_normals(mode)) {
        out.normal.assign(out.world.size(), glm::dvec3(0.0));
        out.normal_error.assign(out.world.size(), 0.0);
        for (uint32_t m = 0; m < scene.meshes.size(); ++m)
            mesh_normals(scene.meshes[m], out.models[m], out.mesh_first_vertex[m], out);
    }
    return out;
}

}  // namespace raster::oracle
