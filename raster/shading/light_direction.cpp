// Light directions (light_direction.h): a directional light's unit direction, a spot light's fade.
#include "raster/shading/light_direction.h"

#include <algorithm>

#include <glm/geometric.hpp>

#include "raster/core/unit_vector.h"

namespace raster {

glm::vec3 directional_to_light(const Light& light) { return unit_or_zero(-light.direction); }

float spot_factor(const Light& light, const glm::vec3& to_light) {
    const SpotFade fade = spot_fade(light);
    const float cd = -glm::dot(unit_or_zero(light.direction), to_light);
    const float f = std::clamp(cd * fade.scale + fade.offset, 0.0f, 1.0f);
    return f * f;
}

}  // namespace raster
