// `raster report` end to end: the report is written, and headless Chromium (Debian `chromium`, installed by
// .ci/install) opens it, renders every row with all its images, and takes a non-trivial screenshot. Without
// Chromium the test fails: it does not skip.
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "apps/cli.h"

namespace raster::cli {
namespace {

namespace fs = std::filesystem;

const std::string kCorpus = std::string(RASTER_SOURCE_DIR) + "/corpus/scenes/";

std::string find_chromium() {
    const char* path = std::getenv("PATH");
    std::istringstream dirs(path ? path : "");
    for (std::string dir; std::getline(dirs, dir, ':');)
        for (const char* name : {"chromium", "chromium-browser"})
            if (::access((fs::path(dir) / name).c_str(), X_OK) == 0) return (fs::path(dir) / name).string();
    return "";
}

std::string read_text(const fs::path& path) {
    std::ifstream file(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
}

// Runs headless Chromium on `page` with a fresh profile; `mode` is "--dump-dom" or "--screenshot=FILE".
// Returns stdout (the DOM for --dump-dom).
std::string run_chromium(const std::string& chromium, const fs::path& work, const std::string& mode, const fs::path& page) {
    static int run = 0;
    const fs::path profile = work / ("profile-" + std::to_string(run++));
    const fs::path out = work / "chromium.out";
    const std::string command = "timeout 120 '" + chromium +
                                "' --headless --no-sandbox --disable-gpu --disable-quic --no-first-run "
                                "--disable-background-networking --disable-component-update --disable-sync "
                                "--user-data-dir='" + profile.string() + "' --window-size=1400,1800 " + mode +
                                " 'file://" + fs::absolute(page).string() + "' > '" + out.string() + "' 2> '" +
                                (work / "chromium.err").string() + "'";
    const int status = std::system(command.c_str());
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << command << "\n" << read_text(work / "chromium.err");
    return read_text(out);
}

size_t occurrences(const std::string& text, const std::string& needle) {
    size_t n = 0;
    for (size_t at = text.find(needle); at != std::string::npos; at = text.find(needle, at + 1)) ++n;
    return n;
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

    const std::string dom = run_chromium(chromium, work, "--dump-dom", dir / "index.html");
    EXPECT_NE(dom.find("data-rows-rendered=\"3\""), std::string::npos) << dom.substr(0, 2000);
    EXPECT_EQ(occurrences(dom, "data-rendered=\"yes\""), 3u);
    EXPECT_EQ(occurrences(dom, "data-rendered=\"no\""), 0u);

    const fs::path shot = work / "report.png";
    run_chromium(chromium, work, "--screenshot=" + shot.string(), dir / "index.html");
    ASSERT_TRUE(fs::exists(shot));
    EXPECT_GT(fs::file_size(shot), 20000u);  // three rows of pictures, not a blank page
    const std::string png = read_text(shot);
    ASSERT_GE(png.size(), 24u);
    EXPECT_EQ(png.substr(1, 3), "PNG");
    const auto be32 = [&](size_t at) {
        return (uint32_t(uint8_t(png[at])) << 24) | (uint32_t(uint8_t(png[at + 1])) << 16) |
               (uint32_t(uint8_t(png[at + 2])) << 8) | uint32_t(uint8_t(png[at + 3]));
    };
    EXPECT_EQ(be32(16), 1400u);  // IHDR width and height: the window
    EXPECT_EQ(be32(20), 1800u);

    // The check can fail: with one image gone, its row is no longer marked rendered.
    fs::remove(dir / summary["scenes"][1]["images"]["oracle"].get<std::string>());
    const std::string broken = run_chromium(chromium, work, "--dump-dom", dir / "index.html");
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
