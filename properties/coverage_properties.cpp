// Coverage properties: samples placed exactly on shared edges and shared vertices are covered exactly once, and a
// triangle's covered samples equal an independent exact-integer computation on its snapped vertices (the tiling
// check, tiling_check.h, on pairs through samples, fans around samples and single triangles).
#include "properties/generators.h"
#include "properties/property_registry.h"
#include "properties/tiling_check.h"

namespace raster::properties {

// Two triangles sharing an edge built to run through samples (horizontal, vertical, diagonal, any slope).
RASTER_RENDERER_PROPERTY(Coverage, sharedEdgeSamplesCoveredExactlyOnce) {
    check_tiling(impl, *pairs_sharing_an_edge_through_samples());
}

// A fan of three to nine triangles around a vertex placed exactly on a sample.
RASTER_RENDERER_PROPERTY(Coverage, sharedVertexOnASampleCoveredExactlyOnce) {
    check_tiling(impl, *fans_around_a_sample());
}

// One triangle (random, axis-aligned, sliver, tiny, on pixel centres, off the snap grid), any sample pattern and
// snap precision, in perspective or not: its samples are exactly the reference's.
RASTER_RENDERER_PROPERTY(Coverage, coveredSamplesEqualTheExactIntegerReference) {
    check_tiling(impl, *single_triangles());
}

}  // namespace raster::properties
