// The viewer's routes on cpp-httplib: what each path answers, the Host check, refusals as plain text, the log line.
#include "apps/viewer_server.h"

#include <sys/socket.h>

#include <chrono>
#include <cstdio>
#include <mutex>
#include <optional>

#include <httplib.h>

#include "apps/viewer_page.h"
#include "raster/core/stopwatch.h"

namespace raster::cli {
namespace {

constexpr const char* kHost = "127.0.0.1";
constexpr const char* kPlainText = "text/plain; charset=utf-8";
constexpr const char* kPaths = "the viewer serves /, /render, /check, /check-map, /state and /log";

// When this thread's current request arrived (set before routing, read by the log line).
thread_local std::optional<Clock::time_point> request_start;

void answer(httplib::Response& response, int status, const std::string& body, const char* content_type) {
    response.status = status;
    response.set_content(body, content_type);
}

void refuse(httplib::Response& response, int status, const std::string& message) {
    answer(response, status, message + "\n", kPlainText);
}

// A request target fit for one log line: at most 300 bytes, anything but printable ASCII as '?'.
std::string loggable(const std::string& text) {
    std::string shown;
    for (const char c : text.substr(0, 300)) shown += (c >= 0x20 && c < 0x7f) ? c : '?';
    return text.size() > 300 ? shown + "..." : shown;
}

std::string milliseconds(double ms) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3f", ms);
    return text;
}

// Like cpp-httplib's default socket options, but without SO_REUSEPORT, which would let a second viewer bind a port
// the first already listens on (and take some of its connections) instead of failing.
void reuse_address_only(socket_t socket) {
    int yes = 1;
    ::setsockopt(socket, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
}

}  // namespace

struct ViewerServer::Routes {
    ViewerSession& session;
    std::ostream& log;
    std::mutex log_mutex;
    httplib::Server server;
    int port = -1;

    Routes(ViewerSession& session_, std::ostream& log_) : session(session_), log(log_) {
        server.set_socket_options(reuse_address_only);
        server.set_default_headers({{"Cache-Control", "no-store"}, {"X-Content-Type-Options", "nosniff"}});
        server.set_keep_alive_timeout(1);
        server.set_pre_routing_handler([this](const httplib::Request& request, httplib::Response& response) {
            request_start = Clock::now();
            return host_allowed(request) ? httplib::Server::HandlerResponse::Unhandled
                                         : refuse_host(request, response);
        });
        server.Get("/", [](const httplib::Request&, httplib::Response& response) {
            answer(response, 200, viewer_page_html(), "text/html; charset=utf-8");
        });
        server.Get("/render", [this](const httplib::Request& request, httplib::Response& response) {
            render(request, response);
        });
        server.Get("/check", [this](const httplib::Request& request, httplib::Response& response) {
            check(request, response);
        });
        server.Get("/check-map", [this](const httplib::Request& request, httplib::Response& response) {
            check_map(request, response);
        });
        server.Get("/state", [this](const httplib::Request&, httplib::Response& response) {
            answer(response, 200, session.state().dump(), "application/json");
        });
        server.Get("/log", [this](const httplib::Request&, httplib::Response& response) {
            answer(response, 200, session.log().dump(), "application/json");
        });
        const auto get_only = [](const httplib::Request& request, httplib::Response& response) {
            refuse(response, 405, "method " + loggable(request.method) + " not allowed: " + kPaths + " to GET only");
        };
        server.Post(".*", get_only).Put(".*", get_only).Patch(".*", get_only).Delete(".*", get_only);
        server.set_error_handler(httplib::Server::HandlerWithResponse([](const httplib::Request& request,
                                                                          httplib::Response& response) {
            if (!response.body.empty()) return httplib::Server::HandlerResponse::Unhandled;  // already explained
            if (response.status == 404)
                refuse(response, 404, "not found: " + loggable(request.path) + " (" + kPaths + ")");
            else
                refuse(response, response.status, "bad request (status " + std::to_string(response.status) + ")");
            return httplib::Server::HandlerResponse::Handled;
        }));
        server.set_exception_handler([](const httplib::Request&, httplib::Response& response,
                                        std::exception_ptr error) {
            std::string what = "unknown exception";
            try {
                std::rethrow_exception(error);
            } catch (const std::exception& exception) {
                what = exception.what();
            } catch (...) {
            }
            refuse(response, 500, "internal error: " + what);
        });
        server.set_logger([this](const httplib::Request& request, const httplib::Response& response) {
            write_log_line(request, response);
        });
    }

    // A browser sends the Host it was pointed at. Refusing any other (a page of another site that resolves its
    // own name to 127.0.0.1, DNS rebinding) keeps other sites' scripts from reading the viewer.
    bool host_allowed(const httplib::Request& request) const {
        if (!request.has_header("Host")) return true;
        const std::string host = request.get_header_value("Host");
        const std::string suffix = ":" + std::to_string(port);
        return host == kHost + suffix || host == "localhost" + suffix ||
               (port == 80 && (host == kHost || host == "localhost"));
    }

    httplib::Server::HandlerResponse refuse_host(const httplib::Request& request, httplib::Response& response) {
        refuse(response, 403,
               "forbidden: Host " + loggable(request.get_header_value("Host")) + " is not this viewer (open http://" +
                   kHost + ":" + std::to_string(port) + "/)");
        return httplib::Server::HandlerResponse::Handled;
    }

    void render(const httplib::Request& request, httplib::Response& response) {
        const ParsedViewRequest parsed = parse_view_request(request.params);
        if (!parsed.error.empty()) return refuse(response, 400, parsed.error);
        try {
            const ViewerFrame frame = session.render(parsed.request);
            response.set_header("X-Frame-Ms", milliseconds(frame.record.frame_ms));
            response.set_header("X-Encode-Ms", milliseconds(frame.record.encode_ms));
            response.set_header("X-Frame-Index", std::to_string(frame.record.index));
            response.set_header("X-Png-Fnv1a64", hex64(frame.record.png_fnv1a));
            answer(response, 200, frame.png, "image/png");
        } catch (const ViewRequestError& error) {
            refuse(response, 400, error.what());
        }
    }

    // GET /check: the oracle's verdict on the frame the parameters make (GET /render's), as JSON.
    void check(const httplib::Request& request, httplib::Response& response) {
        const ParsedViewRequest parsed = parse_view_request(request.params);
        if (!parsed.error.empty()) return refuse(response, 400, parsed.error);
        try {
            answer(response, 200, session.check(parsed.request).result.dump(), "application/json");
        } catch (const ViewRequestError& error) {
            refuse(response, 400, error.what());
        }
    }

    // GET /check-map?index=N: check N's disagreement map, while it is the last check.
    void check_map(const httplib::Request& request, httplib::Response& response) {
        const std::string text = request.get_param_value("index");
        const bool digits = !text.empty() && text.size() <= 19 && text.find_first_not_of("0123456789") == std::string::npos;
        if (!digits || request.params.size() != 1)
            return refuse(response, 400, "check-map takes one parameter, index, a check's number (sent: " +
                                             loggable(request.target) + ")");
        const std::optional<std::string> map = session.check_map(std::stoull(text));
        if (!map) return refuse(response, 404, "check " + text + "'s map is gone: the viewer keeps the last check's only");
        answer(response, 200, *map, "image/png");
    }

    void write_log_line(const httplib::Request& request, const httplib::Response& response) {
        const std::string ms = request_start ? milliseconds(milliseconds_since(*request_start)) : "-";
        request_start.reset();
        const std::lock_guard<std::mutex> lock(log_mutex);
        log << "raster view: " << loggable(request.method) << ' ' << loggable(request.target) << ' '
            << response.status << ' ' << ms << " ms" << std::endl;
    }
};

ViewerServer::ViewerServer(ViewerSession& session, std::ostream& log)
    : routes_(std::make_unique<Routes>(session, log)) {}

ViewerServer::~ViewerServer() = default;

int ViewerServer::bind(int port) {
    httplib::Server& server = routes_->server;
    if (port == 0) {
        routes_->port = server.bind_to_any_port(kHost);
    } else {
        routes_->port = server.bind_to_port(kHost, port) ? port : -1;
    }
    return routes_->port;
}

bool ViewerServer::serve() { return routes_->port > 0 && routes_->server.listen_after_bind(); }

bool ViewerServer::serving() const { return routes_->server.is_running(); }

void ViewerServer::stop() { routes_->server.stop(); }

}  // namespace raster::cli
