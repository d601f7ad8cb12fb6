// Depth properties against the real rasterizer, or RASTER_PROPERTY_MUTANT's bug (depth_properties.h says what each checks and derives its bounds).
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "properties/depth_properties.h"

namespace raster::properties {

RC_GTEST_PROP(Depth, isMonotoneInViewDistanceOverNearToFar, ()) { check_depth_is_monotone_in_view_distance_over_near_to_far(implementation_under_test()); }

RC_GTEST_PROP(Depth, zBufferKeepsTheNearestSurface, ()) { check_the_z_buffer_keeps_the_nearest_surface(implementation_under_test()); }

RC_GTEST_PROP(Depth, imageDoesNotDependOnDrawOrderWithoutTies, ()) { check_the_image_does_not_depend_on_draw_order_without_ties(implementation_under_test()); }

}  // namespace raster::properties
