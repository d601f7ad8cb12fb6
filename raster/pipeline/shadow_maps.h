// Shadow maps: for each light that casts shadows, a cube of six depth images rendered from the light by raster's
// own rasterizer, and the lookup that turns them into the light's visibility at a shaded point (README "Shadows").
#pragma once

#include <cstddef>
#include <vector>

#include <glm/vec3.hpp>

#include "raster/core/cube_faces.h"
#include "raster/pipeline/frame.h"
#include "raster/pipeline/stages.h"
#include "raster/scene/scene.h"

namespace raster {

// One light's cube map.
struct ShadowCube {
    glm::vec3 light{0.0f};
    float near = 0.0f, far = 0.0f;  // the faces' clip planes (shadow_clip_planes)
    // kCubeFaces faces of resolution^2 texels, face by face (cube_faces.h order), each row by row from the top: the
    // view depth of the nearest opaque surface at the texel's centre, +inf where there is none.
    std::vector<float> depth;
};

// The faces' near and far planes for a light: far is twice the largest distance (max norm) from the light to a
// vertex of the scene, near is far / 2^16 (and at least 2^-100); a light on every vertex gets far = 1. Surfaces
// nearer the light than `near` cast no shadow from it.
struct ShadowClipPlanes {
    float near = 0.0f, far = 0.0f;
};
ShadowClipPlanes shadow_clip_planes(const std::vector<glm::vec3>& world_positions, const glm::vec3& light);

// How the maps are rendered: by the stages and the renderer the frame itself uses.
struct ShadowRenderOptions {
    RasterPath path = RasterPath::tiled;
    bool allow_simd = true;
    int threads = 0;
};

class ShadowMaps {
public:
    ShadowMaps() = default;  // no light casts shadows
    // Renders a cube for every light of `scene` that casts shadows, from every scene triangle (both faces; snapped
    // at the default sub-pixel precision, one sample at each texel centre, full clipping, reversed-Z, fixed-point
    // edges), with `world_positions` the vertex stage's world positions of the scene's vertices.
    ShadowMaps(const Scene& scene, const std::vector<glm::vec3>& world_positions, const PipelineStages& stages,
               const ShadowRenderOptions& options);

    bool empty() const { return cubes_.empty(); }
    // Whether scene light `light` has a map.
    bool casts(size_t light) const { return light < cube_of_light_.size() && cube_of_light_[light] >= 0; }
    // The fraction of the filter's texels that see `point` lit by scene light `light` (1 for a light without a map),
    // for a point on a surface with geometric normal `normal` (any length; it sets the slope bias).
    float visibility(size_t light, const glm::vec3& point, const glm::vec3& normal) const;
    const ShadowCube& cube(size_t light) const { return cubes_[static_cast<size_t>(cube_of_light_[light])]; }
    const ShadowSettings& settings() const { return settings_; }

private:
    ShadowSettings settings_;
    std::vector<int> cube_of_light_;  // per scene light: its cube in cubes_, or -1
    std::vector<ShadowCube> cubes_;
};

// The bias of README "Shadows" for a point at depth `depth` on the face, at face coordinates (s, t), on a surface
// whose plane satisfies normal . (x - light) = plane (plane = normal . (point - light)): the constant part plus
// slope_bias times how far the plane comes towards the light over the square of half-side reach = pcf / 2 texels
// around (s, t), that part at most `depth`.
float shadow_bias(const ShadowSettings& settings, const CubeFace& face, float depth, float s, float t,
                  const glm::vec3& normal, float plane);

}  // namespace raster
