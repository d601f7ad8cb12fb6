// Watertightness properties: meshes split into triangles that share edges and vertices cover every sample of their
// union exactly once and nothing outside, in every orientation and sub-pixel offset, from tiny to the fixed-point
// limit. Each is the tiling check (tiling_check.h) on one family of meshes.
#include "properties/generators.h"
#include "properties/property_registry.h"
#include "properties/tiling_check.h"

namespace raster::properties {

// Random convex polygons, fanned from a corner or from an inside point.
RASTER_RENDERER_PROPERTY(Watertight, convexPolygonFansCoverEveryInsideSampleExactlyOnce) {
    check_tiling(impl, *convex_polygon_fans());
}

// Grids of quads with jittered inner vertices, each quad split along a random diagonal.
RASTER_RENDERER_PROPERTY(Watertight, jitteredGridsCoverEverySampleOfTheirRectangleExactlyOnce) {
    check_tiling(impl, *jittered_grids());
}

// Strips of triangles between two rails.
RASTER_RENDERER_PROPERTY(Watertight, triangleStripsCoverEverySampleBetweenTheirRailsExactlyOnce) {
    check_tiling(impl, *triangle_strips());
}

}  // namespace raster::properties
