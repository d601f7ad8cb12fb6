// The derived precision of reversed-Z float depth (conventions.h), shared by the depth, projection and extreme
// properties. With n = near, f = far and u = 2^-24 (float unit roundoff), the projection stores
// m22 = fl(n / (f - n)) and m32 = fl(n f / (f - n)); a view-space point at depth w gets z = fl(fl(m22 * -w) + m32)
// and setup stores d = fl(z / w). Exactly, d(w) = n (f - w) / (w (f - n)): 1 at near, 0 at far, decreasing.
#pragma once

namespace raster::properties {

// The documented depth, in double.
double reversed_z_depth(double w, double near, double far);

// |d(near) - 1|: the entries' rounding moves z(near) by u (m32 + m22 n) = u n (f + n) / (f - n), the product and the
// sum add u m22 n + u n, and the stored d one more u, so |d - 1| <= u ((f + 2n) / (f - n) + 2); twice that is the
// bound, covering the second-order terms.
double depth_error_at_near(double near, double far);

// |d(far)|: z(far) = m32 - m22 f vanishes exactly; rounding the entries leaves u (m32 + m22 f) = 2 u n f / (f - n),
// the product adds u m22 f, so |d(far)| <= 3 u n / (f - n) (1 + O(u)) <= 2^-22 n / (f - n).
double depth_error_at_far(double near, double far);

// Strict monotonicity: d(w1) > d(w2) whenever near <= w1 < w2 <= far and w2 >= w1 (1 + kDistinctDepthGap). The
// exact difference is m32 (w2 - w1) / (w1 w2) >= m32 r / w2 with r = w2 / w1 - 1; the error of each d is at most
// u (m22 + 3 d) <= u (m32 / w2 + 3 m32 (1 + r) / w2) since m22 <= m32 / f <= m32 / w2, so the order is kept when
// r > 2 u (4 + 3 r), that is r > 8u / (1 - 6u) ~ 2^-21; 2^-19 leaves a factor of four for the double division.
inline constexpr double kDistinctDepthGap = 1.0 / (1 << 19);

// The error of the depth the rasterizer compares at a sample: each vertex's d carries at most u (3 m22 + 3 d_i)
// (the entries' rounding, the product, the sum, the division), interpolation with non-negative screen weights
// keeps the largest, and storing the result as float adds u d; so it is below 2^-22 (m22 + max_i d_i).
double interpolated_depth_error(double near, double far, double largest_vertex_depth);

}  // namespace raster::properties
