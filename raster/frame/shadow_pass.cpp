// The shadow pass: each face of each light's cube through the vertex stage, the front end and the backend's
// depth-only draw.
#include "raster/frame/shadow_pass.h"

#include <algorithm>

#include <glm/common.hpp>

#include "raster/transform/cube_faces.h"
#include "raster/geometry/front_end.h"
#include "raster/geometry/vertex_stage.h"
#include "raster/transform/camera_matrices.h"

namespace raster {
namespace {

// The camera of face `face` of a light's cube: at the light, 90 degrees, square (docs/shadows.md).
Camera face_camera(const glm::vec3& light, int face, const ShadowClipPlanes& planes) {
    Camera camera;
    camera.eye = light;
    camera.target = light + cube_face(face).axis;
    camera.up = cube_face(face).up;
    camera.fov_y_degrees = 90.0f;
    camera.near = planes.near;
    camera.far = planes.far;
    return camera;
}

// Renders one face into `depth` (resolution^2 texels): the view depth of the nearest surface at each texel centre.
// `transparent` is transparent_triangles(scene). `workspace` holds the setups, reused from face to face.
void render_face(const Scene& scene, const std::vector<uint8_t>& transparent, const Camera& camera,
                 const RasterBackend& backend, int threads, int resolution, RenderWorkspace& workspace,
                 float* depth) {
    const TransformedScene geometry = run_vertex_stage(scene, VertexStageNeeds{}, view_matrix(camera),
                                                       projection_matrix(camera, resolution, resolution));
    FrameParams frame = frame_params(resolution, resolution, kDefaultSnapBits);
    frame.clip = ClipVolume{camera.near, camera.far, 1.0};
    frame.threads = threads;
    set_up_triangles_into(geometry, frame, /*cull_backfaces=*/false, transparent, workspace.front_end);
    backend.draw_depth(frame, workspace, depth);
}

}  // namespace

ShadowClipPlanes shadow_clip_planes(const std::vector<glm::vec3>& world_positions, const glm::vec3& light) {
    float farthest = 0.0f;
    for (const glm::vec3& p : world_positions) {
        const glm::vec3 d = glm::abs(p - light);
        farthest = std::max({farthest, d.x, d.y, d.z});
    }
    ShadowClipPlanes planes;
    planes.far = farthest > 0.0f ? std::min(2.0f * farthest, 0x1p126f) : 1.0f;
    planes.near = std::max(planes.far * 0x1p-16f, 0x1p-100f);
    return planes;
}

ShadowMaps render_shadow_maps(const Scene& scene, const std::vector<glm::vec3>& world_positions,
                              const RasterBackend& backend, int threads) {
    ShadowMaps maps(scene.settings.shadows, scene.lights.size());
    const int n = scene.settings.shadows.resolution;
    const size_t face_texels = static_cast<size_t>(n) * static_cast<size_t>(n);
    const std::vector<uint8_t> transparent = transparent_triangles(scene);
    RenderWorkspace workspace;
    for (size_t light = 0; light < scene.lights.size(); ++light) {
        if (!scene.lights[light].shadows) continue;
        ShadowCube& cube = maps.add_cube(light);
        cube.light = scene.lights[light].position;
        const ShadowClipPlanes planes = shadow_clip_planes(world_positions, cube.light);
        cube.near = planes.near;
        cube.far = planes.far;
        cube.depth.resize(kCubeFaces * face_texels);
        for (int face = 0; face < kCubeFaces; ++face)
            render_face(scene, transparent, face_camera(cube.light, face, planes), backend, threads, n, workspace,
                        cube.depth.data() + static_cast<size_t>(face) * face_texels);
    }
    return maps;
}

}  // namespace raster
