// The evidence behind a comparison's pixels, for the report's pixel inspector: for each pixel that needs
// explaining (a sample that is not "agree", a colour outside its bounds, a shadow or a transparent layer that left
// it open), every sample's class with the excuse's figure and bound, what each renderer saw there (triangle,
// barycentrics, view depth), and the pixel's bytes on both sides with the interval allowed. Built inside
// compare_scene (ComparisonOptions::evidence_pixels), where the reference geometry and the bounds are at hand, and
// written beside the scene's page, only for those pixels, so a large frame's page stays small.
#pragma once

#include <cstddef>
#include <vector>

#include <glm/vec2.hpp>
#include <nlohmann/json.hpp>

#include "oracle/compare/colour_check.h"
#include "oracle/reference/reference_geometry.h"
#include "raster/image/image.h"

namespace raster::harness {

struct Comparison;

struct EvidenceInputs {
    const Comparison* comparison = nullptr;  // its classes, buffers, images and verdicts, all filled in
    const oracle::ReferenceGeometry* reference = nullptr;
    const std::vector<glm::dvec2>* offsets = nullptr;  // the sample positions inside a pixel
    const oracle::PixelBounds* bounds = nullptr;
    size_t max_pixels = 20000;
};

// {samples, channels, pixels: {"x,y": {samples: [[class, raster triangle, [b0, b1, b2], raster depth,
//  oracle triangle, [b0, b1, b2], oracle depth, excuse rule, measured, bound], ... one per sample], state (judged,
//  ambiguous or genuine), raster: [bytes of the PNG as decoded, or null when no colour image was written],
//  oracle: [bytes], allowed: [[lo, hi] per channel] (judged pixels) or null, colour: agree | genuine | shadow |
//  transparency | null, shadows: [the shadow verdicts met] (with lights that cast shadows), layers: edge | depth |
//  order | null (with transparency)}}, listed, unlisted}: up to `max_pixels` pixels, row by row from the top; a
// triangle is -1 where there is none, a measured and bound null where the excuse is a yes or no; `unlisted` counts
// the pixels left out past the cap. Numbers keep float's precision (9 significant digits), figures 4.
nlohmann::json pixel_evidence(const EvidenceInputs& inputs);

}  // namespace raster::harness
