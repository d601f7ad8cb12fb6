// Depth: reversed-Z float depth (the one depth mode raster has; conventions.h) is strictly monotone in view distance
// over [near, far], the z-buffer keeps the nearest surface, and without ties the image does not depend on draw order.
#pragma once

#include <vector>

#include "properties/generators.h"
#include "properties/implementation.h"

namespace raster::properties {

// For near <= w1 < w2 <= far with w2 >= w1 (1 + 2^-19) (depth_precision.h), the depth setup stores, fl(z / w)
// from the implementation's projection matrix, is strictly larger (nearer) at w1, at every lens from typical to
// near = 1e-6, far = 1e9 and far = near (1 + 2^-10).
void check_depth_is_monotone_in_view_distance_over_near_to_far(const Implementation& impl);

// Overlapping triangles (flat layers, tilted, intersecting) projected with the implementation's lens: every sample
// shows the triangle nearest along its ray, found exactly on the snapped triangles (1/w is affine in screen
// space); samples where the two nearest depths are within the derived error of the compared depth
// (depth_precision.h) are ties and may show either.
void check_the_z_buffer_keeps_the_nearest_surface(const Implementation& impl);

// Fronto-parallel triangles at distinct power-of-two depths (no two surfaces ever tie) drawn in two orders give the
// same visibility buffer, bit for bit: the same triangle, barycentrics and depth at every sample.
void check_the_image_does_not_depend_on_draw_order_without_ties(const Implementation& impl);

// Projects view-space triangles with the implementation's lens (90 degrees, the frame's aspect, the frame's clip
// volume) into clip space.
std::vector<ClipTriangle> project(const Implementation& impl, const LayeredCase& c);

}  // namespace raster::properties
