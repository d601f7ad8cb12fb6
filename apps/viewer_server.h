// `raster view`'s HTTP server on 127.0.0.1: the page, GET /render, /check, /check-map, /state and /log, plain-text
// refusals, and one line per request on the log stream.
#pragma once

#include <memory>
#include <ostream>

#include "apps/viewer_session.h"

namespace raster::cli {

class ViewerServer {
public:
    // Serves `session`'s frames; writes one line per request to `log` (method, target, status, ms). Both outlive it.
    ViewerServer(ViewerSession& session, std::ostream& log);
    ~ViewerServer();
    ViewerServer(const ViewerServer&) = delete;
    ViewerServer& operator=(const ViewerServer&) = delete;

    // Binds 127.0.0.1:port, or a free port the system picks when port is 0, refusing a port another socket holds.
    // Returns the port bound, or -1 when it cannot be bound.
    int bind(int port);

    // Answers requests until stop(). False when it could not serve (bind() did not succeed).
    bool serve();

    // Whether serve() is accepting connections.
    bool serving() const;

    // Makes serve() return once it has started serving; callable from another thread.
    void stop();

private:
    struct Routes;
    std::unique_ptr<Routes> routes_;
};

}  // namespace raster::cli
