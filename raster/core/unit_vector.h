// Unit vectors of any finite size: a direction from a vector whose squared length float cannot hold.
#pragma once

#include <glm/vec3.hpp>

namespace raster {

// v / |v|, or zero for a zero or non-finite vector. |v|^2 overflows float past |v| of about 1.8e19 and loses its
// precision under about 1e-19 (the cross product of a face 1e10 or 1e-10 across); such a vector is first scaled by
// a power of two, which is exact. Any other vector takes the plain v / |v|, so its bits are what they always were.
glm::vec3 unit_or_zero(const glm::vec3& v);

}  // namespace raster
