// A scene's page in the report: its verdict and why, raster's image, the oracle's and the disagreement map large,
// with one zoom and pan, a swipe between raster and the oracle and the pixel readout (scene_page_assets.h), the
// diff map's legend, and every count of the comparison.
#pragma once

#include <string>

#include "oracle/report/report.h"

namespace raster::oracle {

// The page for `row`, linking back to index.html. Every text is HTML-escaped; nothing comes from the network.
std::string scene_page_html(const ReportRow& row);

}  // namespace raster::oracle
