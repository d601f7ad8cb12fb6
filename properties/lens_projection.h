// Projects the view-space triangles of a layered case with the implementation's lens, for the depth and extreme
// properties that draw them.
#pragma once

#include <vector>

#include "properties/generators.h"
#include "properties/implementation.h"

namespace raster::properties {

// Projects view-space triangles with the implementation's lens (90 degrees, the frame's aspect, the frame's clip
// volume) into clip space.
std::vector<ClipTriangle> project(const Implementation& impl, const LayeredCase& c);

}  // namespace raster::properties
