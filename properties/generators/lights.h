// The light generator for the lighting property: a surface normal, a direction towards the light in front of it, a
// distance and a colour.
#pragma once

#include <ostream>
#include <string>

#include <glm/vec3.hpp>
#include <rapidcheck.h>

namespace raster::properties {

struct LightCase {
    std::string kind;
    glm::vec3 normal;     // unit
    glm::vec3 direction;  // unit, from the point towards the light, n . direction > 0
    float distance;
    glm::vec3 color;
};
std::ostream& operator<<(std::ostream& os, const LightCase& c);
rc::Gen<LightCase> lights();

}  // namespace raster::properties
