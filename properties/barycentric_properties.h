// Barycentrics: on every covered sample of a triangle inside the frustum they sum to 1 and are non-negative within
// derived bounds, and they reproduce both the sample's screen position and the 3D point where its ray meets the
// triangle's plane.
//
// The bounds, with u = 2^-24. The rasterizer computes exact screen weights l_i = E_i / area2 (integers, then one
// double division), multiplies by the stored 1 / w_i (a float: relative error u), normalises in double and stores
// each barycentric as a float (relative error u). So each barycentric is the exact perspective-correct one for the
// SNAPPED triangle times (1 + e_i) with |e_i| <= 2u + u + O(u^2) = 1.5 * 2^-23 (the normalisation doubles the
// inverse-w error).
#pragma once

#include "properties/implementation.h"

namespace raster::properties {

// |b0 + b1 + b2 - 1| <= u (|b0| + |b1| + |b2|) (1 + 2u) + 2^-50: in double the normalised weights sum to 1 within a
// few double ulps; storing each as a float moves it by at most u |b_i|.
void check_barycentrics_sum_to_one_within_the_derived_bound(const Implementation& impl);

// b_i >= 0 exactly (bound 0): a covered sample has every E_i >= 0, the weights are products and sums of
// non-negative numbers, and rounding never turns a non-negative number negative.
void check_barycentrics_are_non_negative_on_covered_samples(const Implementation& impl);

// The clip-space point sum b_i v_i projects to within 2^-(snap_bits + 1) + 2^-22 * diameter + 2^-30 pixels of
// the sample in each coordinate: the exact weights reproduce the sample from the snapped vertices, and the
// original vertices are at most half a snap unit away from those (a convex combination keeps that), while the
// relative errors e_i move the projection by at most 2 max|e_i| times the triangle's diameter in pixels.
void check_barycentrics_reproduce_the_sample_screen_position(const Implementation& impl);

// Lift the snapped triangle back to 3D at the original view depths (its projection is exactly what was drawn):
// then sum b_i V_i is the point R where the sample's ray meets that triangle's plane, within
// 2^-22 (max_i |V_i - R| + |R|) + 2^-40 (max_i |V_i| + |R|) (the errors e_i, then the reference's double solve),
// and the reported view depth is R's within 2^-22 relative (1/w rounded to float, the reciprocal stored as float).
void check_perspective_correct_barycentrics_reproduce_the_ray_plane_intersection(const Implementation& impl);

}  // namespace raster::properties
