// The model generator: the loader's scale-rotate-translate chains and a triangle in object space, for the model
// and normal matrix properties.
#pragma once

#include <array>
#include <ostream>
#include <string>

#include <glm/vec3.hpp>
#include <rapidcheck.h>

#include "properties/building_blocks.h"

namespace raster::properties {

struct ModelCase {
    std::string kind;
    ScaleRotateTranslate chain;
    std::array<glm::vec3, 3> triangle;  // object space
};
std::ostream& operator<<(std::ostream& os, const ModelCase& c);
rc::Gen<ModelCase> models();  // non-uniform and mirrored scales from 1e-3 to 1e3, any rotation, far translations

}  // namespace raster::properties
