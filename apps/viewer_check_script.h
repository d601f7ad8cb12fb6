// The viewer page's oracle check: the button that asks GET /check for the frame on screen, the disagreement map laid
// over the frame, the counts and the legend, and the overlay hidden once the view moves on.
#pragma once

namespace raster::cli {

// JavaScript for the page's script element; uses the page's view, renderParams, showPng, serverGone and fnv1a64.
const char* viewer_check_script();

}  // namespace raster::cli
