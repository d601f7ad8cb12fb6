// The disagreement map: one pixel per pixel, red where a sample disagrees genuinely, magenta where every sample
// agrees but the colour is outside its range, yellow where a sample is only ambiguous, and the raster image in
// dimmed grey where everything agrees.
#pragma once

#include <cstdint>
#include <vector>

#include "oracle/compare/raster_output.h"
#include "oracle/compare/sample_classifier.h"
#include "raster/image/image.h"

namespace raster::oracle {

inline constexpr uint8_t kGenuineColor[3] = {230, 20, 20};
inline constexpr uint8_t kColourDisagreementColor[3] = {220, 40, 220};
inline constexpr uint8_t kAmbiguousColor[3] = {250, 210, 0};

// `classes` holds width * height * samples entries in visibility-buffer order, `colour_genuine` one flag per pixel
// (check_colours' genuine_pixels); `raster_image` is width x height. An agreeing pixel is grey at 20 + 35% of the
// raster image's luma, so the scene stays recognisable underneath.
Image diff_map(const std::vector<SampleClass>& classes, int samples, const std::vector<uint8_t>& colour_genuine,
               const RasterPixels& raster_image);

}  // namespace raster::oracle
