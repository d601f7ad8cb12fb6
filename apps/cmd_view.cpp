// `raster view`: loads a scene and serves a page on 127.0.0.1 that renders it as its controls and the mouse ask,
// until SIGINT or SIGTERM.
#include <pthread.h>
#include <signal.h>

#include <atomic>
#include <chrono>
#include <memory>
#include <thread>

#include "apps/command.h"
#include "apps/settings_flags.h"
#include "apps/viewer_server.h"
#include "apps/viewer_session.h"
#include "raster/core/errors.h"
#include "raster/formats/scene_loader.h"

namespace raster::cli {
namespace {

struct ViewFlags {
    std::string scene;
    int port = 8080;
    SettingsFlags settings;
};

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
      far * max(1, distance) (README "Viewer").
  /state   JSON: the scene, its settings and camera, the limits, frames served, the last frame.
  /log     JSON: every frame served (up to 1000), with its parameters, eye, times and PNG hash (FNV-1a 64).
Exit codes: 0 stopped by SIGINT (Ctrl-C) or SIGTERM, 1 the port cannot be bound, 2 bad usage or scene.
Example: raster view corpus/scenes/teapot.yaml --port 0)";

void register_view_flags(CLI::App& app, ViewFlags& flags) {
    CLI::App* view = app.add_subcommand("view", "Serve a local web page that renders a scene interactively.");
    view->footer(kViewFooter);
    view->add_option("scene", flags.scene, "Scene file (any format `raster render` reads)")->required();
    view->add_option("--port", flags.port, "Port on 127.0.0.1 (default 8080; 0 picks a free port)")
        ->check(CLI::Range(0, 65535));
    register_settings_flags(*view, flags.settings);
}

// Blocks SIGINT and SIGTERM in this thread and every thread it starts (the server's and the renderer's), so that
// only the waiter takes them, with sigtimedwait, and stops the server outside any signal handler; the destructor
// restores the mask.
class StopSignals {
public:
    StopSignals() {
        sigemptyset(&signals_);
        sigaddset(&signals_, SIGINT);
        sigaddset(&signals_, SIGTERM);
        pthread_sigmask(SIG_BLOCK, &signals_, &previous_);
    }
    ~StopSignals() { pthread_sigmask(SIG_SETMASK, &previous_, nullptr); }
    StopSignals(const StopSignals&) = delete;
    StopSignals& operator=(const StopSignals&) = delete;

    // Waits up to `timeout` for one of the signals; true when one came.
    bool wait(std::chrono::milliseconds timeout) const {
        const timespec wait_for{static_cast<time_t>(timeout.count() / 1000),
                                static_cast<long>(timeout.count() % 1000) * 1000000L};
        return sigtimedwait(&signals_, nullptr, &wait_for) > 0;
    }

private:
    sigset_t signals_;
    sigset_t previous_;
};

// Serves until a stop signal; false when the server could not serve.
bool serve_until_stopped(ViewerServer& server, const StopSignals& signals) {
    std::atomic<bool> finished{false};
    std::thread waiter([&] {
        while (!finished && !signals.wait(std::chrono::milliseconds(100))) {
        }
        // A signal that comes before the server has started serving stops it once it has.
        while (!finished && !server.serving()) std::this_thread::sleep_for(std::chrono::milliseconds(5));
        if (!finished) server.stop();
    });
    const bool served = server.serve();
    finished = true;
    waiter.join();
    return served;
}

int run_view(const ViewFlags& flags, std::ostream& out, std::ostream& err) {
    // First of all, so that no thread ever takes them by default (a Ctrl-C while a large scene loads stops the
    // server as soon as it serves, exit code 0).
    const StopSignals signals;
    Scene scene;
    try {
        scene = load_scene(flags.scene);
        apply_settings_flags(flags.settings, scene);
    } catch (const InputError& error) {
        err << "raster view: error: " << error.what() << "\n";
        return kExitBadInput;
    }
    RenderOptions options;
    options.threads = flags.settings.threads;
    options.alpha = flags.settings.alpha;
    options.keep_visibility = false;  // the page shows colour only
    ViewerSession session(std::move(scene), options);
    ViewerServer server(session, err);
    const int port = server.bind(flags.port);
    if (port < 0) {
        err << "raster view: error: cannot listen on 127.0.0.1:" << flags.port
            << " (is another program using that port? --port 0 picks a free one)\n";
        return kExitCannotServe;
    }
    out << "raster view: http://127.0.0.1:" << port << "/ (Ctrl-C to stop)" << std::endl;
    if (!serve_until_stopped(server, signals)) {
        err << "raster view: error: the server on 127.0.0.1:" << port << " stopped unexpectedly\n";
        return kExitCannotServe;
    }
    err << "raster view: stopped\n";
    return kExitOk;
}

}  // namespace

Command add_view_command(CLI::App& app) {
    auto flags = std::make_shared<ViewFlags>();
    register_view_flags(app, *flags);
    return {app.get_subcommand("view"),
            [flags](std::ostream& out, std::ostream& err) { return run_view(*flags, out, err); },
            [flags] { *flags = ViewFlags{}; }};
}

}  // namespace raster::cli
