// Headless Chromium for the tests that drive a page: finding the browser and dumping a page's DOM once its scripts
// have run (the report's page and the viewer).
#pragma once

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

namespace raster::test_support {

// The chromium (or chromium-browser) on PATH, or "" when there is none.
inline std::string find_chromium() {
    const char* path = std::getenv("PATH");
    std::istringstream dirs(path ? path : "");
    for (std::string dir; std::getline(dirs, dir, ':');)
        for (const char* name : {"chromium", "chromium-browser"})
            if (::access((std::filesystem::path(dir) / name).c_str(), X_OK) == 0)
                return (std::filesystem::path(dir) / name).string();
    return "";
}

inline std::string read_text(const std::filesystem::path& path) {
    std::ifstream file(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
}

// How to run one dump: the window, how much virtual time the page gets, and the wall-clock guard.
struct DumpOptions {
    std::string headless = "--headless";  // or "--headless=new"
    int window_width = 1200, window_height = 1000;
    int virtual_time_ms = 10000;
    int timeout_s = 600;
};

// The DOM of `url` once headless Chromium (a fresh profile under `work`) has run the page's scripts. With a virtual
// time budget Chromium dumps the DOM only when the page is idle (no fetch pending, no task left, the budget's timers
// fired): a state, not a moment, so the dump does not depend on the machine's speed. The timeout only guards
// against a Chromium that hangs. A failed run is a test failure, with Chromium's stderr.
inline std::string dom_after_scripts(const std::string& chromium, const std::filesystem::path& work,
                                     const std::string& url, const DumpOptions& options = {}) {
    static int run = 0;
    const std::filesystem::path profile = work / ("profile-" + std::to_string(run++));
    const std::filesystem::path out = work / "chromium.out", err = work / "chromium.err";
    const std::string command =
        "timeout " + std::to_string(options.timeout_s) + " '" + chromium + "' " + options.headless +
        " --no-sandbox --disable-gpu --disable-quic --no-first-run --disable-background-networking"
        " --disable-component-update --disable-sync --user-data-dir='" + profile.string() + "' --window-size=" +
        std::to_string(options.window_width) + "," + std::to_string(options.window_height) +
        " --virtual-time-budget=" + std::to_string(options.virtual_time_ms) + " --dump-dom '" + url + "' > '" +
        out.string() + "' 2> '" + err.string() + "'";
    const int status = std::system(command.c_str());
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << command << "\n" << read_text(err);
    return read_text(out);
}

}  // namespace raster::test_support
