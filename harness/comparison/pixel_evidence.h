// The evidence behind a comparison's pixels, for the report's pixel inspector: for each pixel where some sample is
// not "agree", every sample's class and what each renderer saw there (triangle, barycentrics, view depth). Written
// beside the scene's page, only for those pixels, so a large frame's page stays small.
#pragma once

#include <cstddef>

#include <nlohmann/json.hpp>

#include "harness/comparison/scene_comparison.h"

namespace raster::harness {

// {samples, pixels: {"x,y": [[class, raster triangle, [b0, b1, b2], raster depth, oracle triangle, [b0, b1, b2],
//  oracle depth], ... one per sample]}, listed, unlisted}: up to `max_pixels` pixels, row by row from the top; a
// triangle is -1 where there is none; `unlisted` counts the pixels left out past the cap. Numbers keep float's
// precision (9 significant digits).
nlohmann::json pixel_evidence(const Comparison& comparison, size_t max_pixels = 20000);

}  // namespace raster::harness
