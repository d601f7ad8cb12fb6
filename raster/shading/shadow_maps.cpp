// Shadow maps: the lookup with its receiver-plane bias and percentage-closer filter.
#include "raster/shading/shadow_maps.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "raster/transform/cube_faces.h"

namespace raster {

ShadowCube& ShadowMaps::add_cube(size_t light) {
    cube_of_light_[light] = static_cast<int>(cubes_.size());
    return cubes_.emplace_back();
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
