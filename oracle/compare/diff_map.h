// The disagreement map: one pixel per pixel, red where a sample disagrees genuinely, magenta where every sample
// agrees but the colour is outside its range, orange where that is explained by a shadow test, yellow where a
// sample is only ambiguous (or the transparent layers leave the pixel open), blue where the shadow model left a
// light's visibility open, and the raster image in dimmed grey where everything agrees.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "oracle/compare/raster_output.h"
#include "oracle/compare/sample_classifier.h"
#include "oracle/reference/oracle_image.h"

namespace raster::oracle {

inline constexpr uint8_t kGenuineColor[3] = {230, 20, 20};
inline constexpr uint8_t kColourDisagreementColor[3] = {220, 40, 220};
inline constexpr uint8_t kAmbiguousColor[3] = {250, 210, 0};
inline constexpr uint8_t kShadowDisagreementColor[3] = {255, 140, 0};
inline constexpr uint8_t kShadowOpenColor[3] = {70, 150, 255};

// A colour of the map and what it means: the legend the report's scene pages and the viewer's check show.
struct DiffMapKey {
    std::array<uint8_t, 3> rgb;
    const char* meaning;
};
// Every colour the map paints; the agreeing grey as it shows a light surface (luma 200).
const std::vector<DiffMapKey>& diff_map_legend();
// The key's colour as a page writes it: "#e61414".
std::string css_colour(const DiffMapKey& key);

// The shadow and transparency layers of the map, per pixel, each optional (null or empty: none): genuine colour
// disagreements a shadow test explains, the shadow verdicts met (ShadowTally bits; an open verdict paints the
// pixel), and the pixels the transparent layers leave open (painted as ambiguous).
struct ShadowLayers {
    const std::vector<uint8_t>* genuine = nullptr;
    const std::vector<uint8_t>* seen = nullptr;
    const std::vector<uint8_t>* layers_open = nullptr;
};

// `classes` holds width * height * samples entries in visibility-buffer order, `colour_genuine` one flag per pixel
// (check_colours' genuine_pixels); `raster_image` is width x height. An agreeing pixel is grey at 20 + 35% of the
// raster image's luma, so the scene stays recognisable underneath. The map is RGB bytes, row by row from the top.
OracleImage diff_map(const std::vector<SampleClass>& classes, int samples, const std::vector<uint8_t>& colour_genuine,
               const RasterPixels& raster_image, const ShadowLayers& shadows = {});

}  // namespace raster::oracle
