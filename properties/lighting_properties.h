// Lighting: a light marked as attenuating falls off with the inverse square of its distance.
#pragma once

#include "properties/implementation.h"

namespace raster::properties {

// Diffuse-only material, one light along a direction in front of the surface: the attenuated diffuse term over the
// unattenuated one is 1 / |L - P|^2 (in double, from the float positions) within 2^-20 relative. Both terms share
// every operation but the division by the float squared distance: the difference's rounding (2u), the dot product
// (3u), the division (u) and the two products after it in each term (4u) add up to 10u < 2^-20, u = 2^-24.
void check_an_attenuated_light_falls_off_with_the_inverse_square_of_distance(const Implementation& impl);

}  // namespace raster::properties
