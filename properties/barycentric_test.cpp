// Barycentric properties against the real rasterizer, or RASTER_PROPERTY_MUTANT's bug (barycentric_properties.h says what each checks and derives its bounds).
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "properties/barycentric_properties.h"

namespace raster::properties {

RC_GTEST_PROP(Barycentrics, sumToOneWithinTheDerivedBound, ()) { check_barycentrics_sum_to_one_within_the_derived_bound(implementation_under_test()); }

RC_GTEST_PROP(Barycentrics, areNonNegativeOnCoveredSamples, ()) { check_barycentrics_are_non_negative_on_covered_samples(implementation_under_test()); }

RC_GTEST_PROP(Barycentrics, reproduceTheSampleScreenPosition, ()) { check_barycentrics_reproduce_the_sample_screen_position(implementation_under_test()); }

RC_GTEST_PROP(Barycentrics, perspectiveCorrectOnesReproduceTheRayPlaneIntersection, ()) { check_perspective_correct_barycentrics_reproduce_the_ray_plane_intersection(implementation_under_test()); }

}  // namespace raster::properties
