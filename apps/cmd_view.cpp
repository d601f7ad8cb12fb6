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
#include "apps/view_flags.h"
#include "apps/viewer_server.h"
#include "apps/viewer_session.h"
#include "raster/core/errors.h"
#include "raster/compat/scene_loader.h"

namespace raster::cli {
namespace {

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
    ViewerCameras cameras;
    try {
        SceneFile file = load_scene_file(flags.scene, load_options(flags.settings));
        scene = std::move(file.scene);
        apply_settings_flags(flags.settings, scene);
        cameras.names = std::move(file.cameras);
        cameras.loaded = flags.settings.camera;
        // Another of the file's cameras: the file read again as it was the first time, drawn from that camera.
        cameras.load = [flags](int camera) {
            SettingsFlags settings = flags.settings;
            settings.camera = camera;
            Scene other = load_scene_file(flags.scene, load_options(settings)).scene;
            apply_settings_flags(settings, other);
            return other;
        };
    } catch (const InputError& error) {
        err << "raster view: error: " << error.what() << "\n";
        return kExitBadInput;
    }
    RenderOptions options;
    options.threads = flags.settings.threads;
    options.alpha = flags.settings.alpha;
    options.keep_visibility = false;  // the page shows colour only
    ViewerSession session(std::move(scene), options, std::move(cameras));
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
    return flags_command<ViewFlags>(app, "view", register_view_flags, run_view);
}

}  // namespace raster::cli
