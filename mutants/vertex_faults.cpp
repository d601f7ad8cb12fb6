// The vertex stage's and the matrix building blocks' faulty variants of the bug catalogue: a faulty builder comes
// with the vertex stage that uses it, since the real vertex stage calls the real builders itself.
#include "mutants/vertex_faults.h"

#include <glm/geometric.hpp>

#include "raster/core/transform.h"

namespace raster::mutants {

// "integer-divided aspect ratio": width / height computed in integers (640 / 480 = 1), so the image is
// stretched horizontally.
TransformedScene vertex_with_integer_aspect(const Scene& scene, const VertexStageNeeds& needs) {
    const int aspect = scene.settings.width / scene.settings.height;
    return run_vertex_stage(scene, needs, view_matrix(scene.camera),
                            perspective_matrix(scene.camera.fov_y_degrees, static_cast<float>(aspect),
                                               scene.camera.near, scene.camera.far));
}

// "normals not transformed by the inverse-transpose": mesh normals are transformed by the model matrix itself,
// which tilts them under non-uniform scale.
TransformedScene vertex_with_model_matrix_normals(const Scene& scene, const VertexStageNeeds& needs) {
    TransformedScene out = run_vertex_stage(scene, needs);
    if (!needs.vertex_normals) return out;
    for (uint32_t mesh = 0; mesh < scene.meshes.size(); ++mesh) {
        const MeshData& data = scene.meshes[mesh].data;
        if (data.normals.size() != data.positions.size()) continue;
        const glm::mat3 model(scene.meshes[mesh].model);
        for (size_t i = 0; i < data.normals.size(); ++i) {
            const glm::vec3 n = model * data.normals[i];
            const float length = glm::length(n);
            out.world_normal[out.mesh_first_vertex[mesh] + i] = length > 0.0f ? n / length : glm::vec3(0.0f);
        }
    }
    return out;
}

// "look-at basis not orthonormal": the camera's up vector is used as its y axis as given, instead of being
// re-orthogonalised (v = w x u), so the view matrix shears whenever up is not perpendicular to the view direction.
glm::mat4 look_at_with_raw_up(const glm::vec3& eye, const glm::vec3& target, const glm::vec3& up) {
    const glm::vec3 w = glm::normalize(eye - target);
    const glm::vec3 u = glm::normalize(glm::cross(up, w));
    const glm::vec3 v = glm::normalize(up);
    glm::mat4 m(1.0f);
    m[0][0] = u.x; m[1][0] = u.y; m[2][0] = u.z; m[3][0] = -glm::dot(u, eye);
    m[0][1] = v.x; m[1][1] = v.y; m[2][1] = v.z; m[3][1] = -glm::dot(v, eye);
    m[0][2] = w.x; m[1][2] = w.y; m[2][2] = w.z; m[3][2] = -glm::dot(w, eye);
    return m;
}

TransformedScene vertex_with_raw_up(const Scene& scene, const VertexStageNeeds& needs) {
    const Camera& camera = scene.camera;
    return run_vertex_stage(scene, needs, look_at_with_raw_up(camera.eye, camera.target, camera.up),
                            projection_matrix(camera, scene.settings.width, scene.settings.height));
}

// "OpenGL [-1, 1] depth mapping": the projection's depth row is OpenGL's (near -> -1, far -> +1, written in float)
// while the depth test keeps the larger value, so the farthest surface wins; at near = 1e-6, far = 1e9 the
// factor (f + n) / (f - n) rounds to 1 and depth collapses.
glm::mat4 perspective_with_opengl_depth(float fov_y_degrees, float aspect, float near, float far) {
    glm::mat4 m = perspective_matrix(fov_y_degrees, aspect, near, far);
    m[2][2] = -(far + near) / (far - near);
    m[3][2] = -2.0f * far * near / (far - near);
    return m;
}

TransformedScene vertex_with_opengl_depth(const Scene& scene, const VertexStageNeeds& needs) {
    const Camera& camera = scene.camera;
    const float aspect = static_cast<float>(scene.settings.width) / static_cast<float>(scene.settings.height);
    return run_vertex_stage(scene, needs, view_matrix(camera),
                            perspective_with_opengl_depth(camera.fov_y_degrees, aspect, camera.near, camera.far));
}

// "model matrix multiplied in the wrong order": each step of the transform chain is multiplied on the right
// (model = model * step) instead of the left, so scale-rotate-translate becomes S * R * T.
glm::mat4 model_matrix_composed_backwards(const ScaleRotateTranslate& chain) {
    glm::mat4 model(1.0f);
    for (const glm::mat4& step : {scale_matrix(chain.scale), rotate_matrix(chain.degrees, chain.axis),
                                  translate_matrix(chain.offset)})
        model = model * step;
    return model;
}

}  // namespace raster::mutants
