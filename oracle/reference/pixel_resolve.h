// The oracle's resolve, as docs/oracle.md defines it: from a pixel's samples to the linear colour a correct raster
// may write, per channel as an interval (every colour its float arithmetic may give), and the oracle's own bytes.
//   SSAA: the mean over the samples of each covered sample's colour, the background for the uncovered ones.
//   MSAA: each triangle of the pixel shaded once, at the first of its samples in pattern order, weighted by how many
//   samples it covers; the background for the uncovered ones.
//   Alpha: RGB is the mean over the covered samples only, alpha the covered fraction; no coverage is the background
//   with alpha 0.
#pragma once

#include <cstdint>

#include <glm/vec3.hpp>

#include "oracle/reference/interval.h"
#include "oracle/reference/shader.h"

namespace raster::oracle {

// A sample as the resolve reads it: the scene triangle it shows (kNoTriangle when none) and a box holding its
// barycentrics (a point for the oracle's own image, the comparison's tolerance box for the check).
struct ResolveSample {
    uint32_t triangle;
    Interval3 bary;
};

struct ResolveSettings {
    int samples = 1;
    bool msaa = false;
    bool alpha = false;
    glm::dvec3 background{0.0};
};

struct PixelColour {
    Interval channel[4];  // R, G, B and, with alpha, the covered fraction
    int channels = 3;
};

// The pixel's linear colour for its `settings.samples` samples, in pattern order; `tally` (optional) gets the
// shadow verdicts its shading met.
PixelColour resolve_pixel(const OracleShader& shader, const ResolveSettings& settings, const ResolveSample* samples,
                          ShadowTally* tally = nullptr);

}  // namespace raster::oracle
