// The extremes' properties against the real rasterizer, or RASTER_PROPERTY_MUTANT's bug (extreme_properties.h says what each checks and derives its bounds).
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "properties/extreme_properties.h"

namespace raster::properties {

RC_GTEST_PROP(Extremes, nearOneMillionthAndFarOneBillionKeepTheNearerSurface, ()) { check_near_one_millionth_and_far_one_billion_keep_the_nearer_surface(implementation_under_test()); }

RC_GTEST_PROP(Extremes, verticesUpTo2To20PixelsOffScreenCoverTheirVisibleSamples, ()) { check_vertices_up_to_2_20_pixels_off_screen_cover_their_visible_samples(implementation_under_test()); }

RC_GTEST_PROP(Extremes, sliversOfAspectOneMillionAreWatertightAndExact, ()) { check_slivers_of_aspect_one_million_are_watertight_and_exact(implementation_under_test()); }

RC_GTEST_PROP(Extremes, trianglesSmallerThanASubPixelCoverExactlyTheReferenceSamples, ()) { check_triangles_smaller_than_a_sub_pixel_cover_exactly_the_reference_samples(implementation_under_test()); }

RC_GTEST_PROP(Extremes, verticesExactlyOnTheNearPlaneAreKeptWithDepthOne, ()) { check_vertices_exactly_on_the_near_plane_are_kept_with_depth_one(implementation_under_test()); }

RC_GTEST_PROP(Extremes, wNearZeroIsClippedBeforeAnyDivide, ()) { check_w_near_zero_is_clipped_before_any_divide(implementation_under_test()); }

RC_GTEST_PROP(Extremes, nonFiniteCoordinatesAreRejectedCleanly, ()) { check_non_finite_coordinates_are_rejected_cleanly(implementation_under_test()); }

RC_GTEST_PROP(Extremes, sceneExtentsNearFloatLimitsRenderExactlyScaled, ()) { check_scene_extents_near_float_limits_render_exactly_scaled(implementation_under_test()); }

}  // namespace raster::properties
