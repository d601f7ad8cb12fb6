// The viewer page's self-test (?selftest=1), a script of its own: a user's input as DOM events through the page's
// handlers, each followed by the frame it brought, and a report of what each frame asked for and showed.
#pragma once

namespace raster::cli {

// The script's functions runSelfTest and animationSelfTest, which the page (viewer_page.h) calls; they use the
// page's own names (frames, view, scene, idle, $).
const char* viewer_self_test_script();

}  // namespace raster::cli
