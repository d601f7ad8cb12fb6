// The reference rasterizer's faulty variants of the bug catalogue, each with the real rasterize_reference's
// signature (that of PipelineStages::reference_rasterize, so they run on the reference renderer only);
// rasterize_faults.cpp describes each bug where it is written.
#pragma once

#include "raster/pipeline/reference_rasterizer.h"

namespace raster::mutants {

using RasterizeStage = decltype(rasterize_reference);

// "affine instead of perspective-correct"
RasterizeStage rasterize_affine;

// "depth buffer initialised with numeric_limits<float>::min()"
RasterizeStage rasterize_with_depth_cleared_to_min;

// "view depth interpolated linearly (w instead of 1/w)"
RasterizeStage rasterize_with_linear_w;

// "barycentrics evaluated at the pixel centre"
RasterizeStage rasterize_with_pixel_centre_barycentrics;

// "no depth test (the first triangle drawn stays)"
RasterizeStage rasterize_without_depth_test;

}  // namespace raster::mutants
