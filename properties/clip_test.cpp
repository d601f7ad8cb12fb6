// Clipping properties against the real rasterizer, or RASTER_PROPERTY_MUTANT's bug (clip_properties.h says what each checks and derives its bounds).
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "properties/clip_properties.h"

namespace raster::properties {

RC_GTEST_PROP(Clip, outputVerticesSatisfyEveryPlaneWithinTheBound, ()) { check_clipped_vertices_satisfy_every_plane_within_the_bound(implementation_under_test()); }

RC_GTEST_PROP(Clip, triangleInsideTheFrustumIsUntouched, ()) { check_a_triangle_inside_the_frustum_is_untouched(implementation_under_test()); }

RC_GTEST_PROP(Clip, clipThenRasterizeCoversExactlyTheInFrustumSamplesOfTheUnclippedTriangle, ()) { check_clip_then_rasterize_covers_exactly_the_in_frustum_samples_of_the_unclipped_triangle(implementation_under_test()); }

RC_GTEST_PROP(Clip, noVertexWithWAtMostZeroReachesADivide, ()) { check_no_vertex_with_w_at_most_zero_reaches_a_divide(implementation_under_test()); }

}  // namespace raster::properties
