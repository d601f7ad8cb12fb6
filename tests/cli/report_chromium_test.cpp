// `raster report` end to end: the report is written, and headless Chromium (Debian `chromium`, installed by
// .ci/install) opens it, loads every row's images, and the page's script marks the rows and answers the pointer over
// a diff map, as the DOM Chromium dumps once the page is idle shows. Without Chromium the test fails: it does not
// skip.
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "apps/cli.h"
#include "tests/support/headless_chromium.h"

namespace raster::cli {
namespace {

namespace fs = std::filesystem;

const std::string kCorpus = std::string(RASTER_SOURCE_DIR) + "/corpus/scenes/";

using test_support::find_chromium;
using test_support::read_text;

// The DOM of the report page `page` once Chromium has loaded it and run its scripts (test_support::dom_after_scripts).
std::string report_dom(const std::string& chromium, const fs::path& work, const fs::path& page) {
    test_support::DumpOptions options;
    options.window_width = 1400;
    options.window_height = 1800;
    return test_support::dom_after_scripts(chromium, work, "file://" + fs::absolute(page).string(), options);
}

size_t occurrences(const std::string& text, const std::string& needle) {
    size_t n = 0;
    for (size_t at = text.find(needle); at != std::string::npos; at = text.find(needle, at + 1)) ++n;
    return n;
}

// A person's use of the page, played by a script the test adds to a copy of it, after the page's own: once the
// page has loaded, the pointer moves to CSS pixel (6, 4) of the first diff map, where the test has put one colour
// disagreement, and to (75, 150) of the second, where there is none. The page's script writes what it shows for
// each into the row's .hover box.
constexpr const char* kPointerScript = R"(<script>
window.addEventListener('load', () => {
  const maps = document.querySelectorAll('img.diff');
  maps[0].dataset.disagreements = JSON.stringify([{x: 8, y: 5, file: 'first.png', raster: [250, 10, 10],
                                                   allowed: [[0, 5], [0, 6], [1, 7]], oracle: [2, 3, 4]}]);
  const pointAt = (image, x, y) => {
    const box = image.getBoundingClientRect();
    image.dispatchEvent(new MouseEvent('mousemove', {clientX: box.left + x, clientY: box.top + y}));
  };
  pointAt(maps[0], 6, 4);
  pointAt(maps[1], 75, 150);
});
</script>
)";

// `page` with kPointerScript added at the end of its body, written beside it (so its images resolve the same).
fs::path with_pointer_script(const fs::path& page) {
    std::string html = read_text(page);
    const size_t end = html.rfind("</body>");
    EXPECT_NE(end, std::string::npos);
    html.insert(end == std::string::npos ? html.size() : end, kPointerScript);
    const fs::path driven = page.parent_path() / "pointed.html";
    std::ofstream(driven, std::ios::binary) << html;
    return driven;
}

// The text of the .hover box of the row of scene `name` in a dumped DOM ("" when the row is not found).
std::string hover_text(const std::string& dom, const std::string& name) {
    const size_t row = dom.find("data-scene=\"" + name + "\"");
    if (row == std::string::npos) return "";
    const std::string open = "<div class=\"hover\">";
    const size_t start = dom.find(open, row);
    if (start == std::string::npos) return "";
    const size_t end = dom.find("</div>", start);
    return dom.substr(start + open.size(), end - start - open.size());
}

class ReportInChromium : public ::testing::Test {
protected:
    void SetUp() override {
        work = fs::temp_directory_path() / ("raster_report_test_" + std::to_string(::getpid()));
        fs::remove_all(work);
        fs::create_directories(work);
    }
    void TearDown() override { fs::remove_all(work); }
    fs::path work;
};

TEST_F(ReportInChromium, everyRowRendersWithAllItsImages) {
    const std::string chromium = find_chromium();
    ASSERT_FALSE(chromium.empty()) << "chromium is not installed (bash .ci/install installs it)";

    const fs::path dir = work / "report";
    std::ostringstream out, err;
    const int code = run({"raster", "report", kCorpus + "single_triangle.yaml", kCorpus + "interpenetrating.yaml",
                          kCorpus + "perspective_quad.yaml", "-o", dir.string()},
                         out, err);
    ASSERT_EQ(code, 0) << err.str();
    EXPECT_NE(out.str().find("3 scenes, 0 with genuine disagreements"), std::string::npos) << out.str();
    const nlohmann::json summary = nlohmann::json::parse(read_text(dir / "summary.json"));
    ASSERT_EQ(summary["scene_count"], 3);
    EXPECT_EQ(summary["scenes"][0]["name"], "single_triangle");
    for (const auto& scene : summary["scenes"])
        for (const char* image : {"raster", "oracle", "diff"})
            EXPECT_TRUE(fs::exists(dir / scene["images"][image].get<std::string>())) << scene["name"] << " " << image;

    const fs::path page = with_pointer_script(dir / "index.html");
    const std::string dom = report_dom(chromium, work, page);
    // The page's script ran on load: every row's three images decoded, so every row is marked rendered.
    EXPECT_NE(dom.find("data-rows-rendered=\"3\""), std::string::npos) << dom.substr(0, 2000);
    EXPECT_EQ(occurrences(dom, "data-rendered=\"yes\""), 3u);
    EXPECT_EQ(occurrences(dom, "data-rendered=\"no\""), 0u);
    // Over a diff map the pointer's CSS pixel maps to an image pixel by the map's scale: single_triangle is 320 x 240
    // shown 240 px wide (the stylesheet's width), so (6, 4) is pixel (8, 5); interpenetrating is 320 x 320, so
    // (75, 150) is (100, 200). At the one disagreement the page lists it, channel by channel; elsewhere the pixel.
    EXPECT_EQ(hover_text(dom, "single_triangle"),
              "(8, 5) first.png: raster 250 10 10, allowed 0-5 0-6 1-7, oracle 2 3 4");
    EXPECT_EQ(hover_text(dom, "interpenetrating"), "(100, 200)");
    EXPECT_EQ(hover_text(dom, "perspective_quad"), "");  // never pointed at

    // The check can fail: with one image gone, its row is no longer marked rendered.
    fs::remove(dir / summary["scenes"][1]["images"]["oracle"].get<std::string>());
    const std::string broken = report_dom(chromium, work, page);
    EXPECT_NE(broken.find("data-rows-rendered=\"2\""), std::string::npos);
    EXPECT_EQ(occurrences(broken, "data-rendered=\"no\""), 1u);
}

TEST_F(ReportInChromium, badInputExitsTwoBeforeWritingAnything) {
    std::ostringstream out, err;
    const fs::path dir = work / "report";
    EXPECT_EQ(run({"raster", "report", kCorpus + "single_triangle.yaml", (work / "missing.yaml").string(), "-o",
                   dir.string()},
                  out, err),
              2);
    EXPECT_NE(err.str().find("missing.yaml"), std::string::npos) << err.str();
    EXPECT_FALSE(fs::exists(dir));
    EXPECT_EQ(run({"raster", "report", kCorpus + "single_triangle.yaml"}, out, err), 2);  // -o is required
}

TEST_F(ReportInChromium, aDirectoryInputContributesEverySceneInIt) {
    std::ostringstream out, err;
    const fs::path scenes = work / "scenes";
    fs::create_directories(scenes);
    fs::copy_file(kCorpus + "single_triangle.yaml", scenes / "b.yaml");
    fs::copy_file(kCorpus + "interpenetrating.yaml", scenes / "a.yaml");
    fs::copy_file(kCorpus + "single_triangle.yaml", scenes / "notes.txt");  // not a scene file
    ASSERT_EQ(run({"raster", "report", scenes.string(), "-o", (work / "report").string(), "--samples", "4"}, out, err), 0)
        << err.str();
    const nlohmann::json summary = nlohmann::json::parse(read_text(work / "report" / "summary.json"));
    ASSERT_EQ(summary["scene_count"], 2);
    EXPECT_EQ(summary["scenes"][0]["name"], "a");
    EXPECT_EQ(summary["scenes"][1]["name"], "b");
    EXPECT_EQ(summary["scenes"][0]["samples"], 4);
}

}  // namespace
}  // namespace raster::cli
