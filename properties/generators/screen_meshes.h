// The screen-space mesh generators (coverage, watertightness, fill rule, sampling, and the extreme slivers and
// sub-pixel triangles). Each mixes random cases with hand-picked extremes and names its kind.
#pragma once

#include <rapidcheck.h>

#include "properties/generators/tiling_case.h"

namespace raster::properties {

rc::Gen<TilingCase> convex_polygon_fans();       // random convex polygons split into fans, any orientation/offset
rc::Gen<TilingCase> jittered_grids();            // grids of quads, inner vertices jittered, split either way
rc::Gen<TilingCase> triangle_strips();           // strips between two rails
rc::Gen<TilingCase> pairs_sharing_an_edge_through_samples();  // the shared edge passes exactly through samples
rc::Gen<TilingCase> fans_around_a_sample();      // the shared vertex is exactly a sample
rc::Gen<TilingCase> single_triangles();          // random, axis-aligned, slivers, tiny, around samples, off-grid
rc::Gen<TilingCase> symmetric_pairs_sharing_an_edge();  // as above, on frames whose sample pattern is symmetric
rc::Gen<TilingCase> grid_sampled_triangles();    // one triangle on a frame with an N x N grid pattern
rc::Gen<TilingCase> sliver_pairs();              // two slivers of aspect ~1e6 sharing their long edge
rc::Gen<TilingCase> sub_pixel_triangles();       // triangles smaller than 1/256 px, and ones under 1 px^2 on a sample

}  // namespace raster::properties
