// Watertightness: meshes split into triangles that share edges and vertices cover every sample of their union
// exactly once and nothing outside, in every orientation and sub-pixel offset, from tiny to the fixed-point limit.
#pragma once

#include "properties/implementation.h"

namespace raster::properties {

// Random convex polygons, fanned from a corner or from an inside point.
void check_convex_polygon_fans_cover_every_inside_sample_exactly_once(const Implementation& impl);

// Grids of quads with jittered inner vertices, each quad split along a random diagonal.
void check_jittered_grids_cover_every_sample_of_their_rectangle_exactly_once(const Implementation& impl);

// Strips of triangles between two rails.
void check_triangle_strips_cover_every_sample_between_their_rails_exactly_once(const Implementation& impl);

}  // namespace raster::properties
