// Matrix properties against the real rasterizer, or RASTER_PROPERTY_MUTANT's bug (matrix_properties.h says what each checks and derives its bounds).
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "properties/matrix_properties.h"

namespace raster::properties {

RC_GTEST_PROP(ViewMatrix, isRigidAndMapsEyeToOriginAndTargetOntoNegativeZ, ()) { check_view_matrix_is_rigid_and_maps_eye_to_origin_and_target_onto_negative_z(implementation_under_test()); }

RC_GTEST_PROP(Projection, mapsNearAndFarPlanesToTheEndsOfTheDepthRange, ()) { check_projection_maps_near_and_far_planes_to_the_ends_of_the_depth_range(implementation_under_test()); }

RC_GTEST_PROP(Projection, mapsTheFrustumEdgesToTheImageBorder, ()) { check_projection_maps_the_frustum_edges_to_the_image_border(implementation_under_test()); }

RC_GTEST_PROP(Matrices, roundTripsThroughTheInversesHold, ()) { check_round_trips_through_the_inverses_hold(implementation_under_test()); }

RC_GTEST_PROP(ModelMatrix, isTranslateTimesRotateTimesScale, ()) { check_model_matrix_is_translate_times_rotate_times_scale(implementation_under_test()); }

RC_GTEST_PROP(NormalMatrix, keepsNormalsPerpendicularToSurfaces, ()) { check_normal_matrix_keeps_normals_perpendicular_to_surfaces(implementation_under_test()); }

}  // namespace raster::properties
