// The oracle's resolve of a pixel that transparent layers reach (docs/transparency.md): each sample's layers
// composited over its opaque surface or the background, sorted front to back or as raster's weighted average, in
// interval arithmetic with the float error raster's compositing can add, then averaged as pixel_resolve.h does.
#pragma once

#include <cstdint>
#include <vector>

#include "oracle/reference/interval.h"
#include "oracle/reference/pixel_resolve.h"
#include "oracle/reference/shader.h"
#include "raster/scene/scene.h"

namespace raster::oracle {

// A sample with its layers: the opaque surface (kNoTriangle when none) and the transparent surfaces in front of
// it, nearest first, each with a box holding its barycentrics.
struct LayeredSample {
    ResolveSample opaque{kNoTriangle, Interval3(glm::dvec3(0.0))};
    std::vector<ResolveSample> layers;
};

// THE COMPOSITE'S FLOAT ERROR. raster blends a sample's n layers with, per layer, 2 products and a sum on the
// colour (t a, then times c, then +=) and 2 roundings on the transmittance (1 - a, then t times it); the weighted
// mode adds the sum of a and one division and one product. Every partial result is a convex combination of
// colours, so each rounding is relative to at most M, the largest magnitude of the colours involved, and the
// transmittance's relative error (gamma_2n) moves the opaque term by as much again. So the sample's colour is
// within gamma(kLayerRoundings n + kCompositeRoundings) M of the exact composite.
inline constexpr int kLayerRoundings = 6;
inline constexpr int kCompositeRoundings = 8;

// The pixel's colour interval. MSAA shades each triangle once per pixel, at the first sample (pattern order)
// where it is the opaque surface or a layer.
PixelColour resolve_layered_pixel(const OracleShader& shader, const ResolveSettings& settings, TransparencyMode mode,
                                  const LayeredSample* samples, ShadowTally* tally = nullptr);

}  // namespace raster::oracle
