// Matrices: the view matrix is rigid and puts the eye at the origin and the target on -z; the projection maps the
// near and far planes to the ends of the depth range and the frustum's edges to the image border; round trips
// through the inverses hold; the model matrix of a scale-rotate-translate chain is T R S; the normal matrix keeps
// normals perpendicular to surfaces. Each takes the building block under test from the implementation.
//
// Bounds use u = 2^-24 and are evaluated in double on the float matrices.
#pragma once

#include "properties/implementation.h"

namespace raster::properties {

// With theta the angle between up and eye - target: the basis w = normalize(eye - target),
// u = normalize(up x w), v = w x u carries |u.w| <= 2^-22 / sin(theta) (the cross product's rounding relative to
// its length |up| sin(theta)), v is orthogonal to both within 2^-22, and every length is 1 within 4u; so
// |R^T R - I| <= e = 2^-21 (1 + 1 / sin theta) entry by entry and |det R - 1| <= 3e. The eye maps within
// 2^-21 |eye|_1 of the origin (three-term float dot products against the double evaluation), and the target within
// e |target - eye| + 2^-22 (|eye| + |target|) + 2^-21 |eye|_1 of (0, 0, -|target - eye|) (float subtraction of
// eye and target turns the direction by 2^-23 (|eye| + |target|) / |target - eye|).
void check_view_matrix_is_rigid_and_maps_eye_to_origin_and_target_onto_negative_z(const Implementation& impl);

// Points anywhere on the near plane get depth 1 and on the far plane depth 0, within depth_error_at_near and
// depth_error_at_far (depth_precision.h), and w equal to their view depth exactly.
void check_projection_maps_near_and_far_planes_to_the_ends_of_the_depth_range(const Implementation& impl);

// Through the implementation's vertex stage, for any image size: points on the frustum's edges at any depth land
// on NDC x = +-1 and y = +-1 within 2^-21 (the vertex's rounding, the float aspect W / H, the entry
// focal / aspect rounded to float, and the product: five roundings of u, well under 8u).
void check_projection_maps_the_frustum_edges_to_the_image_border(const Implementation& impl);

// view * look_at_inverse = I within the view bounds above; projecting then unprojecting (double inverse of the
// float matrix) returns a view-space point within 2^-21 of its largest coordinate (x and y carry one rounding;
// z and w pass through the depth row, whose rounding is below 5u relative after the homogeneous divide); the
// viewport and its inverse return NDC within 2^-21; and normal_matrix(M)^T M = I within 2^-20 kappa, kappa the
// ratio of M's largest to smallest scale factor (each cofactor of R S is rounded relative to its column's scale).
void check_round_trips_through_the_inverses_hold(const Implementation& impl);

// The loader's matrix for a chain "scale, rotate, translate" is translate * rotate * scale: every 3x3 entry is one
// float product R_ij s_j (within u max|s|), the translation column is t exactly, the last row (0, 0, 0, 1); the
// bound is 2^-22 (max|s| + |t|).
void check_model_matrix_is_translate_times_rotate_times_scale(const Implementation& impl);

// A triangle with its face normal as vertex normals, through the implementation's vertex stage with a model
// T R S (mirrors, non-uniform scales up to 1e6 apart): each world normal is perpendicular to the world triangle's
// edges within 2^-20 (1 + kappa + 4 (max|s| max|p| + |t|) / |M e|) in cosine (the object normal's float rounding,
// the inverse-transpose's relative error kappa 2^-22, and the world positions' float rounding against the edge's
// length). The normal-matrix block alone, against edges transformed in double, within 2^-20 (1 + kappa).
void check_normal_matrix_keeps_normals_perpendicular_to_surfaces(const Implementation& impl);

}  // namespace raster::properties
