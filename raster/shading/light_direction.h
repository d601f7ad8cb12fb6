// Light directions: where a directional light comes from, and how a spot light fades off its axis, as the per-point
// lighting and the SIMD kernels both read them.
#pragma once

#include <glm/vec3.hpp>

#include "raster/scene/scene.h"

namespace raster {

// The unit vector towards a directional light, normalize(-direction) in float (unit_or_zero).
glm::vec3 directional_to_light(const Light& light);

// A spot light's fade (scene.h SpotFade) for the unit vector `to_light` from the point to the light:
// f^2 with f = clamp(cd * scale + offset, 0, 1) and cd = -dot(normalize(direction), to_light), in float.
float spot_factor(const Light& light, const glm::vec3& to_light);

}  // namespace raster
