// What a comparison run says: its JSON, a summary for a person, the genuine counts by reason, the first genuine
// samples and pixels in detail, and the disagreement map.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "harness/comparison/scene_comparison.h"
#include "raster/image/image.h"

namespace raster::harness {

// {scene, renderer, width, height, samples, oracle_mode, agree, ambiguous: {edge_band, depth_tie, clip_boundary,
//  facing}, ambiguous_total, ambiguous_fraction: {...}, genuine: {visibility, barycentrics, depth, color, shadow,
//  transparency, depth_image}, genuine_total, genuine_reasons (genuine_reasons below), shadows: {edge, depth, inconsistent} (pixels, with lights that cast
//  shadows), transparency: {edge, depth, order}, pixels: {judged, ambiguous, color_png, color_ppm, depth_png,
//  depth_ppm}, outputs: {color, depth} (whether each was written and judged), max_color_error, max_depth_error,
//  color_disagreements: [...], depth_disagreements: [...], raster_ms, write_ms, oracle_ms, compare_ms}
nlohmann::json comparison_json(const Comparison& comparison);

// A few lines for a person: the counts by reason, the colour and depth checks and the times.
std::string comparison_summary(const Comparison& comparison);

// The genuine counts by reason, "visibility 12, color 3", or "-" when there are none.
std::string genuine_reasons(const Comparison& comparison);

// The first `shown` genuine samples (where, and what each renderer saw there), colour disagreements (the bytes, the
// allowed ranges and the oracle's) and depth image disagreements, one per line, for a failure message.
std::string genuine_details(const Comparison& comparison, int shown = 8);

// The comparison's disagreement map (oracle/compare/diff_map.h) over raster's image.
Image diff_map(const Comparison& comparison);

}  // namespace raster::harness
