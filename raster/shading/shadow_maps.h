// Shadow maps as data that shading reads: for each light that casts shadows, a cube of six depth images (rendered by
// the shadow pass, shadow_pass.h), and the lookup that turns them into the light's visibility at a shaded point
// (docs/shadows.md).
#pragma once

#include <cstddef>
#include <vector>

#include <glm/vec3.hpp>

#include "raster/scene/scene.h"

namespace raster {

struct CubeFace;  // cube_faces.h

// One light's cube map.
struct ShadowCube {
    glm::vec3 light{0.0f};
    float near = 0.0f, far = 0.0f;  // the faces' clip planes (shadow_pass.h's shadow_clip_planes)
    // kCubeFaces faces of resolution^2 texels, face by face (cube_faces.h order), each row by row from the top: the
    // view depth of the nearest opaque surface at the texel's centre, +inf where there is none.
    std::vector<float> depth;
};

class ShadowMaps {
public:
    ShadowMaps() = default;  // no light casts shadows
    // No cube yet, for a scene of `lights` lights; add_cube gives each light that casts shadows its own.
    ShadowMaps(const ShadowSettings& settings, size_t lights) : settings_(settings), cube_of_light_(lights, -1) {}
    // A new, empty cube for scene light `light` (which has none yet), for the shadow pass to fill; the reference
    // holds until the next add_cube.
    ShadowCube& add_cube(size_t light);

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

// The bias of docs/shadows.md for a point at depth `depth` on the face, at face coordinates (s, t), on a surface
// whose plane satisfies normal . (x - light) = plane (plane = normal . (point - light)): the constant part plus
// slope_bias times how far the plane comes towards the light over the square of half-side reach = pcf / 2 texels
// around (s, t), that part at most `depth`.
float shadow_bias(const ShadowSettings& settings, const CubeFace& face, float depth, float s, float t,
                  const glm::vec3& normal, float plane);

}  // namespace raster
