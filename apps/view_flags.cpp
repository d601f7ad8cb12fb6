// `raster view`'s flags and help text.
#include "apps/view_flags.h"

namespace raster::cli {
namespace {

constexpr const char* kViewFooter = R"(The page, at the printed URL (127.0.0.1 only), shows the frame and
its server render time; buttons pick the shading, samples (1, 4, 16), MSAA and texture filter; dragging the
image orbits the camera about the scene's target, the wheel zooms. Every change renders on the server.
Flags set the scene's settings as for `raster render`; the page starts from them. Each request is logged on
stderr: method, target, status, ms.
HTTP API (GET only; anything else, an unknown path or a bad parameter gets a 4xx and a plain-text reason):
  /render?shading=S&samples=N&msaa=0|1&filter=F&yaw=DEG&pitch=DEG&distance=D
      image/png, headers X-Frame-Ms (render time), X-Encode-Ms, X-Frame-Index, X-Png-Fnv1a64. Every parameter
      is optional (omitted: the scene's own). S: unlit, flat, gouraud, phong, blinn-phong, cel, gooch.
      N: 1..16, as the scene's pattern allows. F: nearest, bilinear, trilinear, anisotropic (every textured
      material). yaw in [-360, 360], pitch in [-180, 180] degrees, distance in [0.05, 20]: the eye is
      target + distance * R(up, yaw) R(side, pitch') (eye - target), with the scene's eye, target and up,
      side = (eye - target) x up, and pitch' keeping the elevation within 89 degrees; near * min(1, distance),
      far * max(1, distance) (docs/viewer.md).
  /state   JSON: the scene, its settings and camera, the limits, frames served, the last frame.
  /log     JSON: every frame served (up to 1000), with its parameters, eye, times and PNG hash (FNV-1a 64).
Exit codes: 0 stopped by SIGINT (Ctrl-C) or SIGTERM, 1 the port cannot be bound, 2 bad usage or scene.
Example: raster view corpus/scenes/teapot.yaml --port 0)";

}  // namespace

void register_view_flags(CLI::App& app, ViewFlags& flags) {
    CLI::App* view = app.add_subcommand("view", "Serve a local web page that renders a scene interactively.");
    view->footer(kViewFooter);
    view->add_option("scene", flags.scene, "Scene file (any format `raster render` reads)")->required();
    view->add_option("--port", flags.port, "Port on 127.0.0.1 (default 8080; 0 picks a free port)")
        ->check(CLI::Range(0, 65535));
    register_settings_flags(*view, flags.settings);
}

}  // namespace raster::cli
