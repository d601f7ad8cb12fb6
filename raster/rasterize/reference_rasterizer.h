// The reference rasterizer: every triangle's bounding box sample by sample over the whole frame, in bands of rows.
// Plain enough to read as the definition of coverage and depth that the tiled renderer is checked against.
#pragma once

#include <vector>

#include "raster/geometry/frame_params.h"
#include "raster/geometry/setup.h"
#include "raster/rasterize/visibility_buffer.h"

namespace raster {

// Rasterizes the triangles in order into `out` (resized to width x height x samples). For each sample the
// nearest triangle wins; on an exact depth tie the one drawn first stays. Then each visible sample gets its
// perspective-correct barycentrics in the original triangle and its view depth. The result is the same for any
// thread count: rows are split into bands and each band is processed by one thread, triangles in order.
void rasterize_reference(const std::vector<TriangleSetup>& triangles, const FrameParams& frame, VisibilityBuffer& out);

}  // namespace raster
