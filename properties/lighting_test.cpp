// Lighting properties against the real rasterizer, or RASTER_PROPERTY_MUTANT's bug (lighting_properties.h says what each checks and derives its bounds).
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "properties/lighting_properties.h"

namespace raster::properties {

RC_GTEST_PROP(Lighting, attenuatedLightFallsOffWithTheInverseSquareOfDistance, ()) { check_an_attenuated_light_falls_off_with_the_inverse_square_of_distance(implementation_under_test()); }

}  // namespace raster::properties
