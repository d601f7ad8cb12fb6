// The depth image `raster render --depth-out` and seed 000's shading-depth task write: view depth as greyscale.
#pragma once

#include "raster/image/image.h"
#include "raster/rasterize/visibility_buffer.h"

namespace raster {

// Greyscale depth: per pixel the nearest covered sample's view depth, mapped linearly so that the nearest depth
// in the image is white (255) and the farthest is 32; pixels with no coverage are black.
Image depth_image(const VisibilityBuffer& visibility);

}  // namespace raster
