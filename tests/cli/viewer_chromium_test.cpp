// `raster view` in headless Chromium (Debian `chromium`, installed by .ci/install): the page, opened with
// ?selftest=1, clicks #shading-flat, drags the image and turns the wheel over it as DOM events through the handlers
// a user's input runs, and for an animated scene with two cameras moves the time slider, plays and pauses, and
// picks the other camera, and presses the oracle check, reading its overlay back. The test does not take the page's word for it: it checks the frames the server logged, with
// their parameters and PNG hashes, that the page showed exactly those bytes, and that the log's hashes are of the
// bytes the server sends. Skipped, saying so, when Chromium is not installed.
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/support/headless_chromium.h"
#include "tests/support/temp_dir.h"
#include "tests/support/viewer_process.h"

namespace raster::test_support {
namespace {

namespace fs = std::filesystem;

const std::string kTeapot = std::string(RASTER_SOURCE_DIR) + "/corpus/scenes/teapot.yaml";
// Animated, with two cameras.
const std::string kAlphaCutouts = std::string(RASTER_SOURCE_DIR) + "/corpus/gltf/alpha_cutouts.gltf";

// The DOM of `url` after the page's self-test: Chromium's new headless mode, 20 s of virtual time.
std::string self_test_dom(const std::string& chromium, const fs::path& work, const std::string& url) {
    DumpOptions options;
    options.headless = "--headless=new";
    options.virtual_time_ms = 20000;
    options.timeout_s = 120;
    return test_support::dom_after_scripts(chromium, work, url, options);
}

// The text of the element that opens with `open` (up to the next '<'), with the serializer's escapes undone.
std::string element_text(const std::string& dom, const std::string& open) {
    const size_t start = dom.find(open);
    if (start == std::string::npos) return "";
    const size_t from = dom.find('>', start) + 1;
    std::string text = dom.substr(from, dom.find('<', from) - from);
    for (const auto& [escaped, plain] : {std::pair<std::string, std::string>{"&quot;", "\""}, {"&lt;", "<"},
                                         {"&gt;", ">"}, {"&amp;", "&"}})
        for (size_t at = text.find(escaped); at != std::string::npos; at = text.find(escaped, at + 1))
            text.replace(at, escaped.size(), plain);
    return text;
}

// 64-bit FNV-1a, the test's own.
std::string fnv1a_hex(const std::string& bytes) {
    uint64_t hash = 0xcbf29ce484222325ull;
    for (const unsigned char byte : bytes) hash = (hash ^ byte) * 0x100000001b3ull;
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash));
    return text;
}

std::string query_of(const nlohmann::json& params) {
    std::string query;
    for (const auto& [name, value] : params.items())
        query += (query.empty() ? "" : "&") + name + "=" + value.get<std::string>();
    return query;
}

// The first logged frame after `after` (an index into frames) that `wanted` accepts; null when none.
const nlohmann::json* find_frame(const nlohmann::json& frames, size_t after,
                                 const std::function<bool(const nlohmann::json&)>& wanted) {
    for (size_t i = after + 1; i < frames.size(); ++i)
        if (wanted(frames[i])) return &frames[i];
    return nullptr;
}

// The page's self-test run against a viewer of `scene`: the page's DOM and report, the server's log of frames.
struct SelfTestRun {
    TempDir dir;
    RunningViewer viewer;
    std::string dom;
    nlohmann::json report, log;
};

void run_self_test(const std::string& chromium, const std::string& scene, SelfTestRun& run) {
    run.viewer = start_viewer(scene, run.dir / "viewer.err");
    ASSERT_GT(run.viewer.port, 0) << run.viewer.first_line << "\n" << run.viewer.log();
    run.dom = self_test_dom(chromium, run.dir.path(), run.viewer.url() + "?selftest=1");
    const std::string report_text = element_text(run.dom, "<pre id=\"selftest\"");
    ASSERT_FALSE(report_text.empty()) << "the self-test wrote no report\n" << run.dom.substr(0, 3000);
    run.report = nlohmann::json::parse(report_text);
    run.log = nlohmann::json::parse(run.viewer.client().Get("/log")->body);
}

// The check button, pressed by the self-test: the server logged the check the page showed, of the frame on screen,
// its map is the bytes the page laid over the frame (fetched again here), only the last map is kept, and the page's
// own checks of the overlay held.
void expect_check_of_the_frame_on_screen(SelfTestRun& run) {
    const nlohmann::json& report = run.report;
    const nlohmann::json& frames = run.log["frames"];
    ASSERT_TRUE(report.contains("check")) << "the self-test did not press check";
    const nlohmann::json& shown_check = report["check"];
    ASSERT_EQ(run.log["checks"].size(), 1u);
    const nlohmann::json& logged_check = run.log["checks"][0];
    EXPECT_EQ(logged_check["index"], shown_check["index"]);
    EXPECT_EQ(logged_check["map_png_fnv1a64"], shown_check["map_shown_fnv1a64"]);
    EXPECT_EQ(logged_check["frame_png_fnv1a64"], frames[shown_check["frame_index"].get<size_t>()]["png_fnv1a64"]);
    const std::string map_path = "/check-map?index=" + logged_check["index"].dump();
    const httplib::Result map = run.viewer.client().Get(map_path.c_str());
    ASSERT_TRUE(map);
    EXPECT_EQ(map->status, 200);
    EXPECT_EQ(fnv1a_hex(map->body), logged_check["map_png_fnv1a64"]);
    const std::string next_path = "/check-map?index=" + std::to_string(logged_check["index"].get<int>() + 1);
    EXPECT_EQ(run.viewer.client().Get(next_path.c_str())->status, 404);
    for (const char* check : {"check_judged_the_frame_on_screen", "check_overlay_is_the_servers_map",
                              "check_overlay_lies_over_the_frame", "check_counts_shown", "check_legend_shown",
                              "check_overlay_toggles", "check_hidden_once_the_view_moves"})
        EXPECT_EQ(report["checks"][check], true) << check;
}

TEST(ViewerInChromium, clickingFlatAndDraggingTheImageChangeTheFramesTheServerSends) {
    const std::string chromium = find_chromium();
    if (chromium.empty()) GTEST_SKIP() << "chromium is not installed (bash .ci/install installs it)";
    SelfTestRun run;
    ASSERT_NO_FATAL_FAILURE(run_self_test(chromium, kTeapot, run));
    const std::string& dom = run.dom;
    const nlohmann::json& report = run.report;
    RunningViewer& viewer = run.viewer;
    const nlohmann::json& frames = run.log["frames"];
    SCOPED_TRACE("page report: " + report.dump() + "\nserver log: " + run.log.dump());

    // The server's side. The first frame is the scene's own.
    ASSERT_GE(frames.size(), 1u);
    const nlohmann::json& first = frames[0];
    EXPECT_EQ(first["shading"], "blinn-phong");
    EXPECT_EQ(first["yaw"], 0.0);
    EXPECT_EQ(first["pitch"], 0.0);
    EXPECT_EQ(first["distance"], 1.0);
    // Clicking flat made the page ask for flat, and flat is another image.
    const nlohmann::json* flat = find_frame(frames, 0, [](const nlohmann::json& f) { return f["shading"] == "flat"; });
    ASSERT_NE(flat, nullptr) << "no frame was rendered with shading=flat";
    EXPECT_NE((*flat)["png_fnv1a64"], first["png_fnv1a64"]);
    EXPECT_EQ((*flat)["yaw"], first["yaw"]);
    // Dragging moved the camera: a later flat frame with another yaw and pitch, another eye, another image.
    const nlohmann::json* dragged = find_frame(frames, (*flat)["index"], [&](const nlohmann::json& f) {
        return f["yaw"] != (*flat)["yaw"] || f["pitch"] != (*flat)["pitch"];
    });
    ASSERT_NE(dragged, nullptr) << "no frame after the flat one has another yaw or pitch";
    EXPECT_NE((*dragged)["yaw"], (*flat)["yaw"]);
    EXPECT_NE((*dragged)["pitch"], (*flat)["pitch"]);
    EXPECT_NE((*dragged)["eye"], (*flat)["eye"]);
    EXPECT_EQ((*dragged)["shading"], "flat");
    EXPECT_NE((*dragged)["png_fnv1a64"], (*flat)["png_fnv1a64"]);
    // The wheel moved it back.
    const nlohmann::json* zoomed = find_frame(frames, (*dragged)["index"], [&](const nlohmann::json& f) {
        return f["distance"].get<double>() > (*dragged)["distance"].get<double>();
    });
    ASSERT_NE(zoomed, nullptr) << "no frame after the drag is farther away";
    EXPECT_NE((*zoomed)["png_fnv1a64"], (*dragged)["png_fnv1a64"]);
    // The teapot's lights cast no shadows until the switch turns them on: then every frame has them, another image.
    EXPECT_EQ(first["shadows"], false);
    const nlohmann::json* shadowed = find_frame(frames, (*zoomed)["index"], [](const nlohmann::json& f) { return f["shadows"] == true; });
    ASSERT_NE(shadowed, nullptr) << "no frame after the wheel has shadows";
    EXPECT_NE((*shadowed)["png_fnv1a64"], frames[(*shadowed)["index"].get<size_t>() - 1]["png_fnv1a64"]);

    // The sample count, MSAA and the camera reset: each a logged frame of its kind; the reset back at the scene's own
    // camera, as the first frame was, with the first frame's eye.
    const nlohmann::json* four = find_frame(frames, (*shadowed)["index"], [](const nlohmann::json& f) { return f["samples"] == 4; });
    ASSERT_NE(four, nullptr) << "no frame at 4 samples";
    EXPECT_NE((*four)["png_fnv1a64"], frames[(*four)["index"].get<size_t>() - 1]["png_fnv1a64"]);
    const nlohmann::json* msaa = find_frame(frames, (*four)["index"], [](const nlohmann::json& f) { return f["msaa"] == true; });
    ASSERT_NE(msaa, nullptr) << "no MSAA frame";
    const nlohmann::json* reset = find_frame(frames, (*msaa)["index"], [](const nlohmann::json& f) {
        return f["yaw"] == 0.0 && f["pitch"] == 0.0 && f["distance"] == 1.0;
    });
    ASSERT_NE(reset, nullptr) << "no frame after the reset is at the scene's own camera";
    EXPECT_EQ((*reset)["eye"], first["eye"]);

    // The page showed those frames: the hash it took of the bytes it drew is the logged hash of the same frame.
    // initial, flat, drag, wheel, shadows on, samples 4, msaa, camera reset (the teapot has no texture to filter)
    ASSERT_EQ(report["steps"].size(), 8u);
    for (const nlohmann::json& step : report["steps"]) {
        const nlohmann::json& shown = step["frame"];
        const size_t index = shown["index"];
        ASSERT_LT(index, frames.size()) << step["name"];
        EXPECT_EQ(shown["hash"], frames[index]["png_fnv1a64"]) << step["name"];
        EXPECT_EQ(shown["params"]["shading"], frames[index]["shading"]) << step["name"];
    }
    EXPECT_EQ(report["steps"][1]["frame"]["index"], (*flat)["index"]);
    // The log's hashes are of the bytes the server sends: the dragged frame, asked for again, hashed here.
    const nlohmann::json& dragged_params = report["steps"][2]["frame"]["params"];
    const httplib::Result again = viewer.client().Get(("/render?" + query_of(dragged_params)).c_str());
    ASSERT_TRUE(again);
    EXPECT_EQ(fnv1a_hex(again->body), (*dragged)["png_fnv1a64"]);

    // The check button: on the teapot, however it is viewed, raster agrees with the oracle, with edge-band samples.
    ASSERT_NO_FATAL_FAILURE(expect_check_of_the_frame_on_screen(run));
    EXPECT_EQ(run.log["checks"][0]["verdict"], "pass");
    EXPECT_EQ(run.log["checks"][0]["genuine_total"], 0);
    EXPECT_GT(run.log["checks"][0]["ambiguous_total"].get<int>(), 0);

    // And the page's own verdict.
    EXPECT_EQ(report["pass"], true);
    EXPECT_NE(dom.find("data-selftest=\"pass\""), std::string::npos);
    EXPECT_EQ(viewer.process->stop(SIGTERM, std::chrono::seconds(10)), 0) << viewer.log();
}

TEST(ViewerInChromium, theTimeSliderPlayAndTheCameraButtonsAskForTheirFramesAndGetThem) {
    const std::string chromium = find_chromium();
    if (chromium.empty()) GTEST_SKIP() << "chromium is not installed (bash .ci/install installs it)";
    SelfTestRun run;
    ASSERT_NO_FATAL_FAILURE(run_self_test(chromium, kAlphaCutouts, run));
    const nlohmann::json& frames = run.log["frames"];
    SCOPED_TRACE("page report: " + run.report.dump() + "\nserver log: " + run.log.dump());
    const nlohmann::json state = nlohmann::json::parse(run.viewer.client().Get("/state")->body);
    ASSERT_TRUE(state["animation"].is_object());
    const double middle = (state["animation"]["start"].get<double>() + state["animation"]["end"].get<double>()) / 2;
    // Before the slider moved, no frame asked for an instant; the slider's frame asked for the middle key span's.
    ASSERT_GE(frames.size(), 1u);
    EXPECT_TRUE(frames[0]["time"].is_null());
    const nlohmann::json* scrubbed = find_frame(frames, 0, [](const nlohmann::json& f) { return !f["time"].is_null(); });
    ASSERT_NE(scrubbed, nullptr) << "no frame asked for an instant";
    EXPECT_NEAR((*scrubbed)["time"].get<double>(), middle, 0.01);
    EXPECT_NE((*scrubbed)["png_fnv1a64"], frames[(*scrubbed)["index"].get<size_t>() - 1]["png_fnv1a64"]);
    // Playing asked for a new instant each frame (later, or wrapped past the last key to the first), another image.
    std::vector<const nlohmann::json*> played;
    for (size_t i = (*scrubbed)["index"].get<size_t>() + 1;
         i < frames.size() && frames[i]["camera"] == 0 && frames[i]["shadows"] == (*scrubbed)["shadows"] &&
         frames[i]["transparency"] == (*scrubbed)["transparency"];
         ++i)
        played.push_back(&frames[i]);
    ASSERT_GE(played.size(), 3u);
    for (size_t i = 1; i < played.size(); ++i) {
        EXPECT_NE((*played[i])["time"].get<double>(), (*played[i - 1])["time"].get<double>()) << i;
        EXPECT_NE((*played[i])["png_fnv1a64"], (*played[i - 1])["png_fnv1a64"]) << i;
    }
    // The server poses the instant asked for: the same request again gives the same bytes, another instant others.
    const nlohmann::json& shown = run.report["steps"][4]["frame"];
    ASSERT_EQ(run.report["steps"][4]["name"], "time slider");
    EXPECT_EQ(shown["hash"], (*scrubbed)["png_fnv1a64"]);
    nlohmann::json params = shown["params"];
    const httplib::Result again = run.viewer.client().Get(("/render?" + query_of(params)).c_str());
    ASSERT_TRUE(again);
    EXPECT_EQ(fnv1a_hex(again->body), (*scrubbed)["png_fnv1a64"]);
    // The second camera's button: a frame from camera 1, another image than the frame before it.
    ASSERT_EQ(state["cameras"]["names"], nlohmann::json::array({"camera", "side"}));
    const nlohmann::json* side = find_frame(frames, 0, [](const nlohmann::json& f) { return f["camera"] == 1; });
    ASSERT_NE(side, nullptr) << "no frame was drawn from camera 1";
    EXPECT_EQ(frames[0]["camera"], 0);
    EXPECT_NE((*side)["png_fnv1a64"], frames[(*side)["index"].get<size_t>() - 1]["png_fnv1a64"]);
    EXPECT_NE((*side)["eye"], frames[0]["eye"]);
    // The shadow switch (the leaf's light is a point light) and the transparency switch: each a frame of its own
    // kind, another image than the frame before it.
    const nlohmann::json* shadowed = find_frame(frames, 0, [](const nlohmann::json& f) { return f["shadows"] == true; });
    ASSERT_NE(shadowed, nullptr) << "no frame had shadows";
    EXPECT_NE((*shadowed)["png_fnv1a64"], frames[(*shadowed)["index"].get<size_t>() - 1]["png_fnv1a64"]);
    EXPECT_EQ(frames[0]["transparency"], "sorted");
    const nlohmann::json* opaque =
        find_frame(frames, 0, [](const nlohmann::json& f) { return f["transparency"] == "opaque"; });
    ASSERT_NE(opaque, nullptr) << "no frame was drawn opaque";
    EXPECT_NE((*opaque)["png_fnv1a64"], frames[(*opaque)["index"].get<size_t>() - 1]["png_fnv1a64"]);
    // The texture filter (the leaves are textured): a frame with the filter the page asked for.
    const nlohmann::json* filtered = find_frame(frames, 0, [](const nlohmann::json& f) { return f["filter"] != "scene"; });
    ASSERT_NE(filtered, nullptr) << "no frame asked for a filter";
    EXPECT_EQ(run.report["checks"]["filter_asked_for"], true);
    ASSERT_NO_FATAL_FAILURE(expect_check_of_the_frame_on_screen(run));
    EXPECT_EQ(run.report["pass"], true);
    EXPECT_EQ(run.viewer.process->stop(SIGTERM, std::chrono::seconds(10)), 0) << run.viewer.log();
}

// The page says so when its server is gone: the page as the viewer served it, opened after the viewer stopped (from
// a file, where no request can reach a server), shows the message and marks <body data-server="gone">.
TEST(ViewerInChromium, thePageSaysWhenTheServerIsGone) {
    const std::string chromium = find_chromium();
    if (chromium.empty()) GTEST_SKIP() << "chromium is not installed (bash .ci/install installs it)";
    TempDir dir;
    RunningViewer viewer = start_viewer(kTeapot, dir / "viewer.err");
    ASSERT_GT(viewer.port, 0) << viewer.first_line << "\n" << viewer.log();
    const httplib::Result page = viewer.client().Get("/");
    ASSERT_TRUE(page);
    EXPECT_EQ(viewer.process->stop(SIGTERM, std::chrono::seconds(10)), 0) << viewer.log();
    const fs::path copy = dir / "viewer.html";
    std::ofstream(copy, std::ios::binary) << page->body;
    const std::string dom = self_test_dom(chromium, dir.path(), "file://" + copy.string());
    EXPECT_NE(dom.find("data-server=\"gone\""), std::string::npos) << dom.substr(0, 3000);
    EXPECT_NE(element_text(dom, "<p id=\"status\"").find("The server is gone: raster view has stopped"),
              std::string::npos) << dom.substr(0, 3000);
}

}  // namespace
}  // namespace raster::test_support
