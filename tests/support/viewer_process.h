// `raster view` run as a process for the viewer tests: started on a free port, its URL read from stdout, its
// stderr (the request log) kept in a file, and an HTTP client for it.
#pragma once

#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include <httplib.h>

#include "tests/support/child_process.h"

namespace raster::test_support {

struct RunningViewer {
    std::unique_ptr<ChildProcess> process;
    std::filesystem::path stderr_file;
    std::string first_line;  // what it printed first on stdout
    int port = -1;           // -1 when no URL was printed

    std::string url() const { return "http://127.0.0.1:" + std::to_string(port) + "/"; }
    httplib::Client client() const { return httplib::Client("127.0.0.1", port); }
    std::string log() const {
        std::ifstream in(stderr_file, std::ios::binary);
        return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    }
    // The log once `complete` accepts it, or as it is after `timeout`. A request's line is written after its
    // response is sent, so it can come after the client's next request's, on another connection.
    std::string log_when(const std::function<bool(const std::string&)>& complete,
                         std::chrono::milliseconds timeout = std::chrono::seconds(10)) const {
        const auto deadline = std::chrono::steady_clock::now() + timeout;
        std::string text = log();
        while (!complete(text) && std::chrono::steady_clock::now() < deadline) {
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
            text = log();
        }
        return text;
    }
};

// Starts `raster ARGS` (RASTER_BINARY, or `program`) and reads its first stdout line; the port is that line's
// URL's, if any.
inline RunningViewer start_raster(const std::vector<std::string>& args, const std::filesystem::path& stderr_file,
                                  const std::string& program = RASTER_BINARY) {
    std::vector<std::string> argv = {program};
    argv.insert(argv.end(), args.begin(), args.end());
    RunningViewer viewer;
    viewer.stderr_file = stderr_file;
    viewer.process = std::make_unique<ChildProcess>(argv, stderr_file);
    viewer.first_line = viewer.process->read_line(std::chrono::seconds(20)).value_or("");
    const std::string prefix = "raster view: http://127.0.0.1:";
    if (viewer.first_line.rfind(prefix, 0) == 0) viewer.port = std::stoi(viewer.first_line.substr(prefix.size()));
    return viewer;
}

// `raster view SCENE --port 0 EXTRA...`.
inline RunningViewer start_viewer(const std::string& scene, const std::filesystem::path& stderr_file,
                                  const std::vector<std::string>& extra = {}) {
    std::vector<std::string> args = {"view", scene, "--port", "0"};
    args.insert(args.end(), extra.begin(), extra.end());
    return start_raster(args, stderr_file);
}

}  // namespace raster::test_support
