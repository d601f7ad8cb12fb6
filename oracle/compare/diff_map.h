// The disagreement map: one pixel per pixel, red where a sample disagrees genuinely, yellow where one is only
// ambiguous, and the raster image in dimmed grey where every sample agrees.
#pragma once

#include <vector>

#include "oracle/compare/sample_classifier.h"
#include "raster/image/image.h"

namespace raster::oracle {

inline constexpr uint8_t kGenuineColor[3] = {230, 20, 20};
inline constexpr uint8_t kAmbiguousColor[3] = {250, 210, 0};

// `classes` holds width * height * samples entries in visibility-buffer order; `raster_image` is width x height.
// An agreeing pixel is grey at 20 + 35% of the raster image's luma, so the scene stays recognisable underneath.
Image diff_map(const std::vector<SampleClass>& classes, int samples, const Image& raster_image);

}  // namespace raster::oracle
