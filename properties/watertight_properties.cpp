// Watertightness properties: each is the tiling check on one family of meshes.
#include "properties/watertight_properties.h"

#include "properties/generators.h"
#include "properties/tiling_check.h"

namespace raster::properties {

void check_convex_polygon_fans_cover_every_inside_sample_exactly_once(const Implementation& impl) {
    check_tiling(impl, *convex_polygon_fans());
}

void check_jittered_grids_cover_every_sample_of_their_rectangle_exactly_once(const Implementation& impl) {
    check_tiling(impl, *jittered_grids());
}

void check_triangle_strips_cover_every_sample_between_their_rails_exactly_once(const Implementation& impl) {
    check_tiling(impl, *triangle_strips());
}

}  // namespace raster::properties
