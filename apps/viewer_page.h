// `raster view`'s page: one HTML document with its style and script inline (no external resource), served at /.
#pragma once

#include <string>

namespace raster::cli {

// The page. It reads GET /state, then shows GET /render frames as its controls change: shading (buttons
// #shading-NAME), samples (#samples-1, -4, -16), MSAA (#msaa), texture filter (#filter-NAME), orbit by dragging
// the image (#frame) and zoom by the wheel; #frame-ms shows the server's X-Frame-Ms. Opened with ?selftest=1 it
// plays a click on #shading-flat, a drag and a wheel turn through the same handlers, and writes what each frame
// was into #selftest (JSON) and body[data-selftest] ("pass" or "fail").
const std::string& viewer_page_html();

}  // namespace raster::cli
