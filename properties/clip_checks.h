// The clipping checks on one case, shared by the clip properties, the extreme properties (far off screen, w ~ 0)
// and the regression tests: the clipped vertices against the planes and the original triangle, every clipped w
// against near, and clip-then-rasterize against the homogeneous reference.
//
// The bound. A cut makes p = in + t (out - in), t = d_in / (d_in - d_out), from the inside vertex. With u = 2^-24,
// rounding the plane distances, t, the difference, the product and the sum moves p by at most
// 2^-21 (|in| + |p|) beyond what in and out already carry, and inherited errors are scaled by (1 - t) and t. Over at
// most six cuts every output coordinate is within 6 * 2^-21 S < 2^-18 S of the exact polygon, where S is the
// largest coordinate among the vertices the cuts keep or make (clipping_scale, computed by clipping in double).
#pragma once

#include "properties/generators.h"
#include "properties/implementation.h"

namespace raster::properties {

// The checks classify nothing; callers classify their cases.

// Every clipped vertex is finite, has w >= near - e and w <= far + e, |x| <= w + e and |y| <= w + e with
// e = 2^-18 S; and is the original triangle at its barycentrics within 2^-18 (S + the originals' largest
// coordinate), which sum to 1 within 2^-18.
void check_clipped_vertices(const Implementation& impl, const ClipCase& c);

// Drawn through clip, setup and rasterize, the triangle covers exactly the samples whose ray meets it at a view
// depth in [near, far], except samples within the derived margin of a line where that changes.
void check_clip_then_rasterize(const Implementation& impl, const ClipCase& c);

// No clipped vertex has w < near or a non-finite coordinate.
void check_every_clipped_w_is_at_least_near(const Implementation& impl, const ClipCase& c);

}  // namespace raster::properties
