// Clipping: output vertices satisfy every plane within a derived bound, a triangle inside the frustum passes
// untouched, clip-then-rasterize covers exactly the samples of the unclipped triangle inside the frustum, and no
// w <= 0 reaches a divide.
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

// Every output vertex is finite, has w >= near - e and w <= far + e, |x| <= w + e and |y| <= w + e with
// e = 2^-18 S; and is the original triangle at its barycentrics within 2^-18 (S + the originals' largest
// coordinate) (the barycentrics ride the same cuts, with errors relative to 1), which sum to 1 within 2^-18.
void check_clipped_vertices_satisfy_every_plane_within_the_bound(const Implementation& impl);

// A triangle inside the volume or exactly on its planes (w = near, w = far, x = +-w, y = +-w) comes back as
// itself: three vertices, bit for bit, with unit barycentrics, not marked clipped.
void check_a_triangle_inside_the_frustum_is_untouched(const Implementation& impl);

// Drawn through clip, setup and rasterize, a triangle covers exactly the samples whose ray meets it at a view depth
// in [near, far] (view_volume_reference.h), except samples within the derived distance of a line where that
// changes: half a sub-pixel unit diagonally (snapping) plus max(W, H) 2^-18 S / w_min pixels (the clipped
// vertices' error e over their smallest w, doubled for x/w, in NDC halves).
void check_clip_then_rasterize_covers_exactly_the_in_frustum_samples_of_the_unclipped_triangle(const Implementation& impl);

// No clipped vertex has w <= 0, or w < near, or a non-finite coordinate: setup divides by every w it is given.
void check_no_vertex_with_w_at_most_zero_reaches_a_divide(const Implementation& impl);

// The parts the extreme properties reuse (they classify nothing; callers classify their cases).
void check_clipped_vertices(const Implementation& impl, const ClipCase& c);
void check_clip_then_rasterize(const Implementation& impl, const ClipCase& c);
void check_every_clipped_w_is_at_least_near(const Implementation& impl, const ClipCase& c);

}  // namespace raster::properties
