// The trade-off plot: per scene, each mode's median frame time (log scale) against its colour RMSE, points
// labelled with the mode names, the Pareto front drawn as a staircase and listed. Plain SVG, no script, no fonts
// or anything else from the network.
#pragma once

#include <string>
#include <vector>

#include "harness/tradeoff/tradeoff.h"

namespace raster::harness {

// The whole SVG document, one panel per scene stacked vertically. Every text is XML-escaped.
std::string pareto_svg(const std::vector<SceneTradeoff>& scenes, int reference_grid);

}  // namespace raster::harness
