// Unit vectors of any finite size (unit_vector.h).
#include "raster/core/unit_vector.h"

#include <algorithm>
#include <cfloat>
#include <cmath>

#include <glm/geometric.hpp>

namespace raster {

glm::vec3 unit_or_zero(const glm::vec3& v) {
    const float squared = glm::dot(v, v);
    if (squared >= FLT_MIN && squared <= FLT_MAX) return v / std::sqrt(squared);
    const float largest = std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
    if (!(largest > 0.0f) || !std::isfinite(largest)) return glm::vec3(0.0f);
    int exponent = 0;
    std::frexp(largest, &exponent);  // largest = m 2^exponent, m in [0.5, 1)
    const glm::vec3 scaled(std::ldexp(v.x, -exponent), std::ldexp(v.y, -exponent), std::ldexp(v.z, -exponent));
    return scaled / glm::length(scaled);
}

}  // namespace raster
