// `raster view` as a process (raster-view run in raster's place): the URL on stdout, exit 0 on SIGINT and SIGTERM,
// 1 on a port in use, 2 on a bad scene or a missing viewer program, and over HTTP: plain-text refusals of bad
// requests, a server that keeps serving, one log line a request.
#include <signal.h>

#include <chrono>
#include <regex>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/support/temp_dir.h"
#include "tests/support/viewer_process.h"

namespace raster::test_support {
namespace {

using std::chrono::seconds;

const std::string kTeapot = std::string(RASTER_SOURCE_DIR) + "/corpus/scenes/teapot.yaml";

TEST(ViewerProcess, printsItsUrlAndStopsWithZeroOnSigintOrSigterm) {
    for (const int signal : {SIGINT, SIGTERM}) {
        TempDir dir;
        RunningViewer viewer = start_viewer(kTeapot, dir / "err.txt");
        ASSERT_GT(viewer.port, 0) << viewer.first_line << "\n" << viewer.log();
        EXPECT_EQ(viewer.first_line, "raster view: " + viewer.url() + " (Ctrl-C to stop)");
        const httplib::Result page = viewer.client().Get("/");
        ASSERT_TRUE(page) << httplib::to_string(page.error());
        EXPECT_EQ(page->status, 200);
        EXPECT_EQ(page->get_header_value("Content-Type"), "text/html; charset=utf-8");
        EXPECT_NE(page->body.find("<img id=\"frame\""), std::string::npos);
        EXPECT_EQ(page->body.find("http"), std::string::npos) << "the page loads nothing from elsewhere";
        EXPECT_EQ(viewer.process->stop(signal, seconds(10)), 0) << viewer.log();
        EXPECT_NE(viewer.log().find("raster view: GET / 200 "), std::string::npos) << viewer.log();
        EXPECT_NE(viewer.log().find("raster view: stopped\n"), std::string::npos) << viewer.log();
    }
}

TEST(ViewerProcess, aPortInUseExitsOne) {
    TempDir dir;
    RunningViewer first = start_viewer(kTeapot, dir / "first.txt");
    ASSERT_GT(first.port, 0) << first.log();
    RunningViewer second =
        start_raster({"view", kTeapot, "--port", std::to_string(first.port)}, dir / "second.txt");
    EXPECT_EQ(second.port, -1) << second.first_line;
    EXPECT_EQ(second.process->wait(seconds(20)), 1);
    EXPECT_NE(second.log().find("cannot listen on 127.0.0.1:" + std::to_string(first.port)), std::string::npos)
        << second.log();
    // The first still serves alone: the second did not share its port.
    const httplib::Result state = first.client().Get("/state");
    ASSERT_TRUE(state);
    EXPECT_EQ(state->status, 200);
    EXPECT_EQ(first.process->stop(SIGTERM, seconds(10)), 0);
}

TEST(ViewerProcess, aBadSceneOrFlagExitsTwoBeforeServing) {
    TempDir dir;
    const std::filesystem::path bad = dir.write("bad.yaml", "image: {width: 64, height: 48}\ncamera: {near: -1}\n");
    RunningViewer viewer = start_raster({"view", bad.string(), "--port", "0"}, dir / "err.txt");
    EXPECT_EQ(viewer.process->wait(seconds(20)), 2);
    EXPECT_EQ(viewer.first_line, "");
    EXPECT_NE(viewer.log().find("raster view: error: " + bad.string() + ":2:"), std::string::npos) << viewer.log();
    RunningViewer missing = start_raster({"view", (dir / "missing.yaml").string()}, dir / "missing.txt");
    EXPECT_EQ(missing.process->wait(seconds(20)), 2);
    RunningViewer port = start_raster({"view", kTeapot, "--port", "65536"}, dir / "port.txt");
    EXPECT_EQ(port.process->wait(seconds(20)), 2);
    EXPECT_NE(port.log().find("--port"), std::string::npos) << port.log();
}

// `raster view` runs the viewer program beside `raster`; a `raster` without it says which file is missing.
TEST(ViewerProcess, aRasterWithoutTheViewerProgramBesideItExitsTwoNamingIt) {
    TempDir dir;
    const std::filesystem::path lone = dir / "raster";
    std::filesystem::copy_file(RASTER_BINARY, lone);
    std::filesystem::permissions(lone, std::filesystem::perms::owner_exec, std::filesystem::perm_options::add);
    RunningViewer viewer = start_raster({"view", kTeapot, "--port", "0"}, dir / "err.txt", lone.string());
    EXPECT_EQ(viewer.process->wait(seconds(20)), 2);
    EXPECT_EQ(viewer.first_line, "");
    EXPECT_NE(viewer.log().find("raster view: error: cannot run the viewer program " + (dir / "raster-view").string()),
              std::string::npos)
        << viewer.log();
}

class ViewerHttp : public ::testing::Test {
protected:
    void SetUp() override {
        viewer = start_viewer(kTeapot, dir / "err.txt");
        ASSERT_GT(viewer.port, 0) << viewer.log();
    }
    void TearDown() override {
        if (viewer.process) {
            EXPECT_EQ(viewer.process->stop(SIGTERM, seconds(10)), 0) << viewer.log();
        }
    }

    // The status and body of GET target.
    std::pair<int, std::string> get(const std::string& target) {
        const httplib::Result result = viewer.client().Get(target.c_str());
        if (!result) return {-1, httplib::to_string(result.error())};
        return {result->status, result->body};
    }

    TempDir dir;
    RunningViewer viewer;
};

TEST_F(ViewerHttp, badRequestsGetAPlainTextReasonAndTheServerKeepsServing) {
    const std::pair<int, std::string> refusals[][2] = {
        {{400, "shading must be unlit, flat, gouraud, phong, blinn-phong, cel or gooch, got 'toon'\n"},
         {0, "/render?shading=toon"}},
        {{400, "samples must be in [1, 16], got '64'\n"}, {0, "/render?samples=64"}},
        {{400, "samples must be a whole number, got 'four'\n"}, {0, "/render?samples=four"}},
        {{400, "yaw must be a finite number, got 'NaN'\n"}, {0, "/render?yaw=NaN"}},
        {{400, "pitch must be in [-180, 180] degrees, got '1e300'\n"}, {0, "/render?pitch=1e300"}},
        {{400, "distance must be a finite number, got '1e999'\n"}, {0, "/render?distance=1e999"}},
        {{400, "msaa must be 0 or 1, got 'yes'\n"}, {0, "/render?msaa=yes"}},
        {{400, "the standard pattern has 1, 2, 4, 8 or 16 samples, not 3\n"}, {0, "/render?samples=3"}},
        {{400, "parameter 'yaw' is given more than once\n"}, {0, "/render?yaw=1&yaw=2"}},
        {{404, "not found: /render.png (the viewer serves /, /render, /check, /check-map, /state and /log)\n"},
         {0, "/render.png"}},
        {{400, "samples must be a whole number, got 'x'\n"}, {0, "/check?samples=x"}},
        {{400, "check-map takes one parameter, index, a check's number (sent: /check-map?index=-1)\n"},
         {0, "/check-map?index=-1"}},
        {{404, "check 0's map is gone: the viewer keeps the last check's only\n"}, {0, "/check-map?index=0"}},
    };
    for (const auto& [expected, request] : refusals) {
        const auto [status, body] = get(request.second);
        EXPECT_EQ(status, expected.first) << request.second;
        EXPECT_EQ(body, expected.second) << request.second;
    }
    const httplib::Result posted = viewer.client().Post("/render", "x", "text/plain");
    ASSERT_TRUE(posted);
    EXPECT_EQ(posted->status, 405);
    EXPECT_EQ(posted->get_header_value("Content-Type"), "text/plain; charset=utf-8");
    httplib::Client foreign = viewer.client();
    foreign.set_default_headers({{"Host", "rebound.example:" + std::to_string(viewer.port)}});
    const httplib::Result rebound = foreign.Get("/state");
    ASSERT_TRUE(rebound);
    EXPECT_EQ(rebound->status, 403);
    EXPECT_EQ(rebound->body.rfind("forbidden: Host rebound.example:", 0), 0u) << rebound->body;

    // Still serving, and none of the refusals was a frame.
    const auto [status, body] = get("/render?shading=flat&samples=4&msaa=1&yaw=10&pitch=-5&distance=1.2");
    EXPECT_EQ(status, 200);
    EXPECT_EQ(body.substr(1, 3), "PNG");
    const nlohmann::json log = nlohmann::json::parse(get("/log").second);
    ASSERT_EQ(log["frames"].size(), 1u);
    EXPECT_EQ(log["frames"][0]["shading"], "flat");
    EXPECT_EQ(log["frames"][0]["samples"], 4);

    // One log line per request: method, target, status, milliseconds.
    const std::regex frame_line("raster view: GET /render\\?shading=flat&samples=4&msaa=1&yaw=10&pitch=-5"
                                "&distance=1.2 200 [0-9]+\\.[0-9]{3} ms\n");
    const std::string lines =
        viewer.log_when([&](const std::string& text) { return std::regex_search(text, frame_line); });
    EXPECT_TRUE(std::regex_search(lines, frame_line)) << lines;
    EXPECT_NE(lines.find("raster view: GET /render?shading=toon 400 "), std::string::npos) << lines;
    EXPECT_NE(lines.find("raster view: POST /render 405 "), std::string::npos) << lines;
    EXPECT_NE(lines.find("raster view: GET /render.png 404 "), std::string::npos) << lines;
}

TEST_F(ViewerHttp, aFrameComesWithItsTimesAndHash) {
    const httplib::Result frame = viewer.client().Get("/render?shading=gooch");
    ASSERT_TRUE(frame);
    EXPECT_EQ(frame->status, 200);
    EXPECT_EQ(frame->get_header_value("Content-Type"), "image/png");
    EXPECT_GT(std::stod(frame->get_header_value("X-Frame-Ms")), 0.0);
    EXPECT_GE(std::stod(frame->get_header_value("X-Encode-Ms")), 0.0);
    EXPECT_EQ(frame->get_header_value("X-Frame-Index"), "0");
    const nlohmann::json state = nlohmann::json::parse(viewer.client().Get("/state")->body);
    EXPECT_EQ(state["last_frame"]["png_fnv1a64"], frame->get_header_value("X-Png-Fnv1a64"));
    EXPECT_EQ(state["last_frame"]["png_bytes"], frame->body.size());
    EXPECT_EQ(state["frames_served"], 1);
}

}  // namespace
}  // namespace raster::test_support
