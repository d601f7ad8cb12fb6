// The report's "Speed against accuracy" section: the results of `raster tradeoff` (its Pareto plot, a table per scene
// and links to its CSV and JSON), read defensively from tradeoff.json.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace raster::oracle {

// The results of `raster tradeoff` the page links: `dir` is their folder relative to index.html (holding
// pareto.svg, tradeoff.csv and tradeoff.json), `results` the parsed tradeoff.json.
struct TradeoffLink {
    std::string dir;
    nlohmann::json results;
};

// The section's HTML: a missing or mistyped field shows as "-" or blank, never as an exception.
std::string tradeoff_section(const TradeoffLink& link);

}  // namespace raster::oracle
