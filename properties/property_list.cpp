// The list of properties, one line each; property_list_test.cpp keeps it equal to the RC_GTEST_PROPs.
#include "properties/property_list.h"

#include "properties/barycentric_properties.h"
#include "properties/clip_properties.h"
#include "properties/coverage_properties.h"
#include "properties/depth_properties.h"
#include "properties/extreme_properties.h"
#include "properties/fill_rule_properties.h"
#include "properties/lighting_properties.h"
#include "properties/matrix_properties.h"
#include "properties/sampling_properties.h"
#include "properties/watertight_properties.h"

namespace raster::properties {

const std::vector<Property>& all_properties() {
    static const std::vector<Property> list = {
        {"Watertight", "convexPolygonFansCoverEveryInsideSampleExactlyOnce", check_convex_polygon_fans_cover_every_inside_sample_exactly_once},
        {"Watertight", "jitteredGridsCoverEverySampleOfTheirRectangleExactlyOnce", check_jittered_grids_cover_every_sample_of_their_rectangle_exactly_once},
        {"Watertight", "triangleStripsCoverEverySampleBetweenTheirRailsExactlyOnce", check_triangle_strips_cover_every_sample_between_their_rails_exactly_once},
        {"Coverage", "sharedEdgeSamplesCoveredExactlyOnce", check_shared_edge_samples_are_covered_exactly_once},
        {"Coverage", "sharedVertexOnASampleCoveredExactlyOnce", check_a_shared_vertex_on_a_sample_is_covered_exactly_once},
        {"Coverage", "coveredSamplesEqualTheExactIntegerReference", check_covered_samples_equal_the_exact_integer_reference},
        {"FillRule", "sharedEdgeSamplesBelongToTheTriangleRightOfOrBelowTheEdge", check_shared_edge_samples_belong_to_the_triangle_right_of_or_below_the_edge},
        {"FillRule", "ownershipChangesUnderMirrorsAndQuarterTurnsAsTheRuleSays", check_ownership_changes_under_mirrors_and_quarter_turns_as_the_rule_says},
        {"Barycentrics", "sumToOneWithinTheDerivedBound", check_barycentrics_sum_to_one_within_the_derived_bound},
        {"Barycentrics", "areNonNegativeOnCoveredSamples", check_barycentrics_are_non_negative_on_covered_samples},
        {"Barycentrics", "reproduceTheSampleScreenPosition", check_barycentrics_reproduce_the_sample_screen_position},
        {"Barycentrics", "perspectiveCorrectOnesReproduceTheRayPlaneIntersection", check_perspective_correct_barycentrics_reproduce_the_ray_plane_intersection},
        {"Depth", "isMonotoneInViewDistanceOverNearToFar", check_depth_is_monotone_in_view_distance_over_near_to_far},
        {"Depth", "zBufferKeepsTheNearestSurface", check_the_z_buffer_keeps_the_nearest_surface},
        {"Depth", "imageDoesNotDependOnDrawOrderWithoutTies", check_the_image_does_not_depend_on_draw_order_without_ties},
        {"ViewMatrix", "isRigidAndMapsEyeToOriginAndTargetOntoNegativeZ", check_view_matrix_is_rigid_and_maps_eye_to_origin_and_target_onto_negative_z},
        {"Projection", "mapsNearAndFarPlanesToTheEndsOfTheDepthRange", check_projection_maps_near_and_far_planes_to_the_ends_of_the_depth_range},
        {"Projection", "mapsTheFrustumEdgesToTheImageBorder", check_projection_maps_the_frustum_edges_to_the_image_border},
        {"Matrices", "roundTripsThroughTheInversesHold", check_round_trips_through_the_inverses_hold},
        {"ModelMatrix", "isTranslateTimesRotateTimesScale", check_model_matrix_is_translate_times_rotate_times_scale},
        {"NormalMatrix", "keepsNormalsPerpendicularToSurfaces", check_normal_matrix_keeps_normals_perpendicular_to_surfaces},
        {"Clip", "outputVerticesSatisfyEveryPlaneWithinTheBound", check_clipped_vertices_satisfy_every_plane_within_the_bound},
        {"Clip", "triangleInsideTheFrustumIsUntouched", check_a_triangle_inside_the_frustum_is_untouched},
        {"Clip", "clipThenRasterizeCoversExactlyTheInFrustumSamplesOfTheUnclippedTriangle", check_clip_then_rasterize_covers_exactly_the_in_frustum_samples_of_the_unclipped_triangle},
        {"Clip", "noVertexWithWAtMostZeroReachesADivide", check_no_vertex_with_w_at_most_zero_reaches_a_divide},
        {"Sampling", "gridCoverageConvergesToTheExactAreaWithinAPerimeterBound", check_grid_coverage_converges_to_the_exact_area_within_a_perimeter_bound},
        {"Sampling", "standardPatternsAreTheDocumentedPositions", check_standard_patterns_are_the_documented_positions},
        {"Extremes", "nearOneMillionthAndFarOneBillionKeepTheNearerSurface", check_near_one_millionth_and_far_one_billion_keep_the_nearer_surface},
        {"Extremes", "verticesUpTo2To20PixelsOffScreenCoverTheirVisibleSamples", check_vertices_up_to_2_20_pixels_off_screen_cover_their_visible_samples},
        {"Extremes", "sliversOfAspectOneMillionAreWatertightAndExact", check_slivers_of_aspect_one_million_are_watertight_and_exact},
        {"Extremes", "trianglesSmallerThanASubPixelCoverExactlyTheReferenceSamples", check_triangles_smaller_than_a_sub_pixel_cover_exactly_the_reference_samples},
        {"Extremes", "verticesExactlyOnTheNearPlaneAreKeptWithDepthOne", check_vertices_exactly_on_the_near_plane_are_kept_with_depth_one},
        {"Extremes", "wNearZeroIsClippedBeforeAnyDivide", check_w_near_zero_is_clipped_before_any_divide},
        {"Extremes", "nonFiniteCoordinatesAreRejectedCleanly", check_non_finite_coordinates_are_rejected_cleanly},
        {"Extremes", "sceneExtentsNearFloatLimitsRenderExactlyScaled", check_scene_extents_near_float_limits_render_exactly_scaled},
        {"Lighting", "attenuatedLightFallsOffWithTheInverseSquareOfDistance", check_an_attenuated_light_falls_off_with_the_inverse_square_of_distance},
    };
    return list;
}

}  // namespace raster::properties
