// The style and script of a scene's page in the report (scene_page.h): the three images side by side with one zoom
// and pan, a swipe between raster and the oracle, and a readout of the pixel clicked.
#pragma once

namespace raster::oracle {

// The page's stylesheet: panes of equal size, nearest-neighbour magnification (an image pixel stays a square).
const char* scene_page_style();

// The page's script. Its state is on <body>, for a person's bookmarklet and for headless checks: data-zoom (CSS
// pixels per image pixel), data-pan ("x,y", CSS pixels), data-swipe (the share of raster shown, 0 to 100),
// data-pixel ("x,y", the image pixel last clicked) and data-rendered ("yes" once every image has loaded).
// Controls: the mouse wheel zooms about the pointer, a drag pans, a click reads the pixel under the pointer; the
// buttons fit, zoom in, zoom out and show one image pixel per CSS pixel; the swipe checkbox shows the swipe pane.
const char* scene_page_script();

}  // namespace raster::oracle
