// A mesh file alone as a scene: the mesh, and the camera and light that frame it.
#include "raster/compat/mesh_scene.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <utility>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "raster/core/errors.h"
#include "raster/formats/document.h"
#include "raster/scene/validation.h"
#include "raster/transform/scene_bounds.h"

namespace raster {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr float kFovYDegrees = 45.0f;
constexpr double kMargin = 1.05;  // the bounding sphere's radius is framed as 5% larger

// From the centre towards the eye: 30 degrees above the horizontal, turned 30 degrees from +z towards +x.
glm::dvec3 view_direction() {
    const double elevation = kPi / 6.0, azimuth = kPi / 6.0;
    return {std::cos(elevation) * std::sin(azimuth), std::sin(elevation), std::cos(elevation) * std::cos(azimuth)};
}

}  // namespace

Camera framing_camera(const glm::vec3& centre, float radius_in, float aspect) {
    const double radius = radius_in > 0.0f ? radius_in : 1.0;
    // The sphere fits a field of view whose half-angle is h when the eye is radius / sin(h) from its centre.
    const double half_y = 0.5 * kFovYDegrees * kPi / 180.0;
    const double half_x = std::atan(aspect * std::tan(half_y));
    const double distance = kMargin * radius / std::sin(std::min(half_y, half_x));
    Camera camera;
    camera.eye = glm::vec3(glm::dvec3(centre) + distance * view_direction());
    camera.target = centre;
    camera.up = {0.0f, 1.0f, 0.0f};
    camera.fov_y_degrees = kFovYDegrees;
    camera.near = static_cast<float>(0.9 * (distance - kMargin * radius));  // distance > 2.7 radius: near > 0
    camera.far = static_cast<float>(1.1 * (distance + kMargin * radius));
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

void frame_scene(Scene& scene, bool camera, bool light) {
    if (camera) {
        const std::optional<WorldBounds> bounds = world_bounds(scene);
        if (!bounds) throw InputError(scene.path, 0, 0, "the scene has no triangles to frame");
        const float aspect = static_cast<float>(scene.settings.width) / static_cast<float>(scene.settings.height);
        scene.camera = framing_camera(glm::vec3(bounds->centre), static_cast<float>(bounds->radius), aspect);
        // A camera the file never wrote is not the user's to fix: say what about the meshes makes it unusable.
        if (const std::optional<CameraProblem> problem = camera_problem(scene.camera)) {
            char extent[96];
            std::snprintf(extent, sizeof extent, "radius %g, its centre %g from the origin", bounds->radius,
                          glm::length(bounds->centre));
            throw InputError(scene.path, 0, 0,
                             std::string("the mesh's bounding sphere (") + extent + ") cannot be framed by a float camera (" +
                                 problem->message + "); place it in a scene with a camera of its own");
        }
    }
    if (light) scene.lights = {framing_light(scene.camera)};
}

void read_mesh_file_scene(MeshData data, const std::filesystem::path& path, const SceneFileLoaders& files,
                          Scene& scene) {
    scene.path = path.string();
    SceneMesh mesh;
    mesh.source = path.filename().string();
    mesh.data = shared_mesh_data(std::move(data));
    if (mesh.data->triangles.empty()) throw InputError(scene.path, 0, 0, "the mesh has no triangles to render");
    files.obj_materials(Node::undefined(), mesh.source, mesh, std::nullopt);
    scene.meshes.push_back(std::move(mesh));
    frame_scene(scene, true, true);
}

}  // namespace raster
