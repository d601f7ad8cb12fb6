// Watertightness properties against the real rasterizer, or RASTER_PROPERTY_MUTANT's bug (watertight_properties.h says what each checks and derives its bounds).
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "properties/watertight_properties.h"

namespace raster::properties {

RC_GTEST_PROP(Watertight, convexPolygonFansCoverEveryInsideSampleExactlyOnce, ()) { check_convex_polygon_fans_cover_every_inside_sample_exactly_once(implementation_under_test()); }

RC_GTEST_PROP(Watertight, jitteredGridsCoverEverySampleOfTheirRectangleExactlyOnce, ()) { check_jittered_grids_cover_every_sample_of_their_rectangle_exactly_once(implementation_under_test()); }

RC_GTEST_PROP(Watertight, triangleStripsCoverEverySampleBetweenTheirRailsExactlyOnce, ()) { check_triangle_strips_cover_every_sample_between_their_rails_exactly_once(implementation_under_test()); }

}  // namespace raster::properties
