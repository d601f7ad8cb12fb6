// The comparison report: a self-contained index.html (one row per scene: raster image, oracle image and diff map
// side by side, with counts and timings; images are files beside it, no network) and summary.json.
#pragma once

#include <optional>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace raster::oracle {

// One scene of the report. Image names are file names relative to index.html.
struct ReportRow {
    std::string name;           // the scene file's stem
    nlohmann::json comparison;  // comparison_json of the scene
    std::string raster_image, oracle_image, diff_image;
};

// The results of `raster tradeoff` the page links: `dir` is their folder relative to index.html (holding
// pareto.svg, tradeoff.csv and tradeoff.json), `results` the parsed tradeoff.json.
struct TradeoffLink {
    std::string dir;
    nlohmann::json results;
};

// A file-name stem for a row's images: `name` with every character outside [A-Za-z0-9._-] replaced by '_', with
// "-2", "-3", ... appended until it is not in `taken` (it is then added).
std::string unique_file_stem(const std::string& name, std::set<std::string>& taken);

// The page. Every text is HTML-escaped. An inline script marks each row data-rendered="yes" once all its images
// have loaded (naturalWidth > 0), and sets body's data-rows-rendered to their number, for headless checks.
// With `tradeoff`, a "Speed against accuracy" section follows: the Pareto plot, one table per scene (mode, median
// time, genuine, ambiguous, colour RMSE, coverage error, on the front) and links to the CSV and JSON.
std::string report_html(const std::vector<ReportRow>& rows, const std::optional<TradeoffLink>& tradeoff = std::nullopt);

// {scenes: [comparison + {name, images: {raster, oracle, diff}}], scene_count, genuine_total, scenes_with_genuine}
nlohmann::json report_summary(const std::vector<ReportRow>& rows);

}  // namespace raster::oracle
