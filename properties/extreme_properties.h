// The extremes, each with an explicit expectation: near = 1e-6 with far = 1e9, vertices 2^20 pixels off screen,
// slivers of aspect 1e6, triangles under 1/256 px, vertices exactly on the near plane, w ~ 0, NaN and Inf
// coordinates, and scene extents near the float limits.
#pragma once

#include "properties/implementation.h"

namespace raster::properties {

// Two fronto-parallel quads filling the view at view depths w1 < w2 anywhere in [1e-6, 1e9], w2 >= w1 (1 + 2^-19),
// rendered in either order: every sample shows the nearer quad, at view depth w1 within 2^-22 relative.
void check_near_one_millionth_and_far_one_billion_keep_the_nearer_surface(const Implementation& impl);

// Vertices up to 2^20 px off screen: the clipped vertices satisfy the planes, and the drawn samples are exactly
// the in-frustum samples of the unclipped triangle outside the derived margin (clip_properties.h).
void check_vertices_up_to_2_20_pixels_off_screen_cover_their_visible_samples(const Implementation& impl);

// Two slivers of aspect ~1e6 sharing their long edge (16384 px long at 16 sub-pixel bits, the fixed-point limit,
// or across a 32 px frame): exactly the reference's samples, and the shared edge's samples exactly once.
void check_slivers_of_aspect_one_million_are_watertight_and_exact(const Implementation& impl);

// Triangles smaller than one sub-pixel unit (1/256 px at 8 bits), a few units, or under one square pixel, all at
// a sample: they cover exactly the reference's samples (often none, never a crash, and never dropped for being
// small when their snapped form holds a sample).
void check_triangles_smaller_than_a_sub_pixel_cover_exactly_the_reference_samples(const Implementation& impl);

// One to three vertices exactly on the near plane (the rest inside): the triangle is not clipped, its near
// vertices get depth 1 within depth_error_at_near, and it covers exactly the reference's samples.
void check_vertices_exactly_on_the_near_plane_are_kept_with_depth_one(const Implementation& impl);

// A vertex at w = 0, +-1e-40 (denormal), +-1e-30 or +-near 1e-7: every clipped vertex has w >= near, and the
// drawn samples are the in-frustum ones of the unclipped triangle outside the derived margin.
void check_w_near_zero_is_clipped_before_any_divide(const Implementation& impl);

// NaN or +-Inf in one to three clip coordinates: the clip stage returns nothing and no sample is covered; the same
// number in a scene's vertex makes validate_scene throw InputError. (Run under UBSan: no undefined behaviour.)
void check_non_finite_coordinates_are_rejected_cleanly(const Implementation& impl);

// A scene scaled by 2^k (k up to 120: extents near 2e37; down to -100) renders bit for bit the same ids and
// barycentrics, with view depths scaled by exactly 2^k: every float operation on the way scales exactly while
// nothing overflows or goes subnormal (the generator's ranges are chosen for that, see generators.cpp). And a
// triangle at +-3e38, whose clip coordinates overflow to Inf and NaN, changes nothing else and leaves every
// value in the visibility buffer finite.
void check_scene_extents_near_float_limits_render_exactly_scaled(const Implementation& impl);

}  // namespace raster::properties
