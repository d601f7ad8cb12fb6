// Shadow maps: each face rendered from the light by the frame's own front end and rasterizer, depth only; the
// lookup with its receiver-plane bias and percentage-closer filter.
#include "raster/pipeline/shadow_maps.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

#include "raster/pipeline/front_end.h"
#include "raster/pipeline/setup_table.h"
#include "raster/pipeline/tiled_renderer.h"
#include "raster/pipeline/transparency.h"

namespace raster {
namespace {

constexpr float kNoSurface = std::numeric_limits<float>::infinity();

// The camera of face `face` of a light's cube: at the light, 90 degrees, square (README "Shadows").
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
// `transparent` is transparent_triangles(scene): those cast no shadow (README "Transparency"). `workspace` holds the
// setups, reused from face to face.
void render_face(const Scene& scene, const std::vector<uint8_t>& transparent, const Camera& camera,
                 const PipelineStages& stages, const ShadowRenderOptions& options, int resolution,
                 RenderWorkspace& workspace, float* depth) {
    const TransformedScene geometry = run_vertex_stage(scene, VertexStageNeeds{}, view_matrix(camera),
                                                       projection_matrix(camera, resolution, resolution));
    FrameParams frame = frame_params(resolution, resolution, kDefaultSnapBits);
    frame.clip = ClipVolume{camera.near, camera.far, 1.0};
    frame.threads = options.threads;
    RenderStats stats;
    set_up_triangles_into(geometry, frame, stages, /*cull_backfaces=*/false, stats, workspace);
    split_transparent_setups(transparent, workspace.setup_chunks, workspace.transparent_setups);
    if (options.path == RasterPath::tiled) {
        rasterize_depth_tiled(SetupTable::of_chunks(workspace.setup_chunks), frame, options.allow_simd, depth);
        return;
    }
    concatenate_setups(workspace.setup_chunks, frame.threads, workspace.setups);
    VisibilityBuffer visibility;
    stages.reference_rasterize(workspace.setups, frame, visibility);
    for (size_t i = 0; i < visibility.size(); ++i)
        depth[i] = visibility.triangle[i] == kNoTriangle ? kNoSurface : visibility.view_depth[i];
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

ShadowMaps::ShadowMaps(const Scene& scene, const std::vector<glm::vec3>& world_positions,
                       const PipelineStages& stages, const ShadowRenderOptions& options)
    : settings_(scene.settings.shadows), cube_of_light_(scene.lights.size(), -1) {
    const int n = settings_.resolution;
    const size_t face_texels = static_cast<size_t>(n) * static_cast<size_t>(n);
    const std::vector<uint8_t> transparent = transparent_triangles(scene);
    RenderWorkspace workspace;
    for (size_t light = 0; light < scene.lights.size(); ++light) {
        if (!scene.lights[light].shadows) continue;
        cube_of_light_[light] = static_cast<int>(cubes_.size());
        ShadowCube& cube = cubes_.emplace_back();
        cube.light = scene.lights[light].position;
        const ShadowClipPlanes planes = shadow_clip_planes(world_positions, cube.light);
        cube.near = planes.near;
        cube.far = planes.far;
        cube.depth.resize(kCubeFaces * face_texels);
        for (int face = 0; face < kCubeFaces; ++face)
            render_face(scene, transparent, face_camera(cube.light, face, planes), stages, options, n, workspace,
                        cube.depth.data() + static_cast<size_t>(face) * face_texels);
    }
}

float shadow_bias(const ShadowSettings& settings, const CubeFace& face, float depth, float s, float t,
                  const glm::vec3& normal, float plane) {
    // The plane's depth along the direction axis + s' right + t' up is plane / (normal . that direction): a ratio
    // of linear functions of (s', t'), so over the square its nearest value is at a corner, unless the denominator
    // changes sign there (the plane runs through the light's own position: drop capped at the depth).
    const float reach = static_cast<float>(settings.pcf) / static_cast<float>(settings.resolution);  // pcf/2 texels
    float drop = 0.0f;
    for (int corner = 0; corner < 4; ++corner) {
        const float cs = s + ((corner & 1) ? reach : -reach), ct = t + ((corner & 2) ? reach : -reach);
        const float denominator = glm::dot(normal, face.axis + cs * face.right + ct * face.up);
        if (!(denominator * plane > 0.0f)) {
            drop = depth;
            break;
        }
        drop = std::max(drop, depth - plane / denominator);
    }
    return settings.bias * depth + settings.slope_bias * std::min(drop, depth);
}

float ShadowMaps::visibility(size_t light, const glm::vec3& point, const glm::vec3& normal) const {
    if (!casts(light)) return 1.0f;
    const ShadowCube& cube = this->cube(light);
    const glm::vec3 d = point - cube.light;
    const int face_index = cube_face_of(d);
    const CubeFace& face = cube_face(face_index);
    const float depth = glm::dot(face.axis, d);
    if (!(depth > 0.0f)) return 1.0f;  // the point is the light's own position
    const float s = glm::dot(face.right, d) / depth, t = glm::dot(face.up, d) / depth;
    const float reference = depth - shadow_bias(settings_, face, depth, s, t, normal, glm::dot(normal, d));
    const int n = settings_.resolution;
    const float half = 0.5f * static_cast<float>(n);
    const int column = std::clamp(static_cast<int>(std::floor((s + 1.0f) * half)), 0, n - 1);
    const int row = std::clamp(static_cast<int>(std::floor((1.0f - t) * half)), 0, n - 1);
    const float* texels = cube.depth.data() + static_cast<size_t>(face_index) * static_cast<size_t>(n) * n;
    const int radius = settings_.pcf / 2;
    int lit = 0;
    for (int dy = -radius; dy <= radius; ++dy) {
        const size_t y = static_cast<size_t>(std::clamp(row + dy, 0, n - 1));
        for (int dx = -radius; dx <= radius; ++dx) {
            const size_t x = static_cast<size_t>(std::clamp(column + dx, 0, n - 1));
            lit += texels[y * static_cast<size_t>(n) + x] >= reference;
        }
    }
    return static_cast<float>(lit) / static_cast<float>(settings_.pcf * settings_.pcf);
}

}  // namespace raster
