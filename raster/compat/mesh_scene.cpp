// A mesh file alone as a scene: the mesh, and the camera and light that frame it.
#include "raster/compat/mesh_scene.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "raster/core/errors.h"
#include "raster/formats/document.h"

namespace raster {
namespace {

constexpr float kPi = 3.14159265358979f;
constexpr float kFovYDegrees = 45.0f;
constexpr float kMargin = 1.05f;  // the bounding sphere's radius is framed as 5% larger

// From the centre towards the eye: 30 degrees above the horizontal, turned 30 degrees from +z towards +x.
glm::vec3 view_direction() {
    const float elevation = 30.0f * kPi / 180.0f, azimuth = 30.0f * kPi / 180.0f;
    return {std::cos(elevation) * std::sin(azimuth), std::sin(elevation), std::cos(elevation) * std::cos(azimuth)};
}

}  // namespace

Camera framing_camera(const glm::vec3& centre, float radius, float aspect) {
    if (!(radius > 0.0f)) radius = 1.0f;
    // The sphere fits a field of view whose half-angle is h when the eye is radius / sin(h) from its centre.
    const float half_y = 0.5f * kFovYDegrees * kPi / 180.0f;
    const float half_x = std::atan(aspect * std::tan(half_y));
    const float distance = kMargin * radius / std::sin(std::min(half_y, half_x));
    Camera camera;
    camera.eye = centre + distance * view_direction();
    camera.target = centre;
    camera.up = {0.0f, 1.0f, 0.0f};
    camera.fov_y_degrees = kFovYDegrees;
    camera.near = 0.9f * (distance - kMargin * radius);  // distance > 2.7 radius: near > 0
    camera.far = 1.1f * (distance + kMargin * radius);
    return camera;
}

Light framing_light(const Camera& camera) {
    const glm::vec3 towards_eye = camera.eye - camera.target;
    const glm::vec3 right = glm::normalize(glm::cross(-towards_eye, camera.up));
    const glm::vec3 direction = glm::normalize(glm::normalize(towards_eye) - 0.6f * right + 0.6f * camera.up);
    Light light;
    light.position = camera.target + glm::length(towards_eye) * direction;
    return light;
}

void read_mesh_file_scene(MeshData data, const std::filesystem::path& path, const SceneFileLoaders& files,
                          Scene& scene) {
    scene.path = path.string();
    SceneMesh mesh;
    mesh.source = path.filename().string();
    mesh.data = std::move(data);
    if (mesh.data.triangles.empty()) throw InputError(scene.path, 0, 0, "the mesh has no triangles to render");
    files.obj_materials(Node::undefined(), mesh.source, mesh, std::nullopt);

    glm::vec3 lo = mesh.data.positions[mesh.data.triangles.front().v[0]], hi = lo;
    for (const TriangleIndices& triangle : mesh.data.triangles)
        for (const uint32_t v : triangle.v) {
            lo = glm::min(lo, mesh.data.positions[v]);
            hi = glm::max(hi, mesh.data.positions[v]);
        }
    const glm::vec3 centre = 0.5f * (lo + hi);
    float radius = 0.0f;
    for (const TriangleIndices& triangle : mesh.data.triangles)
        for (const uint32_t v : triangle.v) radius = std::max(radius, glm::length(mesh.data.positions[v] - centre));
    const float aspect = static_cast<float>(scene.settings.width) / static_cast<float>(scene.settings.height);
    scene.camera = framing_camera(centre, radius, aspect);
    scene.lights = {framing_light(scene.camera)};
    scene.meshes.push_back(std::move(mesh));
}

}  // namespace raster
