// The comparison report: a self-contained index.html (a summary table, a row a scene, sortable, failing scenes
// first), a page per scene (scene_page.h: the images large, zoomed and panned together), and summary.json. Images
// are files beside the pages; nothing comes from the network.
#pragma once

#include <optional>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "oracle/report/tradeoff_section.h"

namespace raster::oracle {

// One scene of the report. Image names are file names relative to index.html.
struct ReportRow {
    std::string name;           // the scene file's stem
    nlohmann::json comparison;  // comparison_json of the scene
    std::string raster_image, oracle_image, diff_image;
    std::string page;      // the scene's own page (scene_page.h)
    std::string evidence;  // the script beside it that holds its pixels' evidence for the inspector; "" for none
};

// A file-name stem for a row's images: `name` with every character outside [A-Za-z0-9._-] replaced by '_', with
// "-2", "-3", ... appended until it is not in `taken` (it is then added).
std::string unique_file_stem(const std::string& name, std::set<std::string>& taken);

// The index page: a table with a row per scene (verdict, why, genuine and ambiguous counts, the excused share, the
// widest colour interval, samples, renderer, both times and the diff map's thumbnail, each scene linking to its
// page), failing scenes first; a click on a header sorts by it. Every text is HTML-escaped. An inline script marks
// each row data-rendered="yes" once its thumbnail has loaded, and sets body's data-rows-rendered to their number.
// With `tradeoff`, a "Speed against accuracy" section follows: the Pareto plot, one table per scene (mode, median
// time, genuine, ambiguous, colour RMSE, coverage error, on the front) and links to the CSV and JSON.
std::string report_html(const std::vector<ReportRow>& rows, const std::optional<TradeoffLink>& tradeoff = std::nullopt);

// {scenes: [comparison + {name, images: {raster, oracle, diff}, page}], scene_count, genuine_total,
//  scenes_with_genuine}
nlohmann::json report_summary(const std::vector<ReportRow>& rows);

}  // namespace raster::oracle
