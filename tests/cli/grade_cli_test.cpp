// `raster grade` on the command line: an image raster rendered passes (exit 0) with its JSON and mask written, an
// image drawn with another sample pattern than promised fails (exit 1), and bad input exits 2 naming the file.
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/support/cli_run.h"
#include "tests/support/temp_dir.h"

namespace raster::cli {
namespace {

namespace fs = std::filesystem;

const std::string kCorpus = std::string(RASTER_SOURCE_DIR) + "/corpus/scenes/";

using test_support::CliRun;
using test_support::run_raster;
using test_support::TempDir;

TEST(GradeCli, rastersOwnImagePassesWithItsJsonAndMask) {
    const TempDir dir;
    const std::string image = (dir / "teapot.png").string();
    ASSERT_EQ(run_raster({"render", kCorpus + "teapot.yaml", "-o", image}).code, 0);
    const CliRun r = run_raster({"grade", kCorpus + "teapot.yaml", image, "--json", (dir / "grade.json").string(),
                                 "--mask", (dir / "mask.png").string()});
    ASSERT_EQ(r.code, 0) << r.out << r.err;
    EXPECT_EQ(r.out.rfind("PASS: ", 0), 0u) << r.out;
    std::ifstream file(dir / "grade.json");
    const nlohmann::json json = nlohmann::json::parse(file);
    EXPECT_EQ(json["verdict"], "pass");
    EXPECT_EQ(json["failing"], 0);
    uint64_t pixels = 0;
    for (const auto& [grade, count] : json["pixels"].items()) pixels += count.get<uint64_t>();
    EXPECT_EQ(pixels, 800u * 800u);
    EXPECT_GT(fs::file_size(dir / "mask.png"), 100u);
}

TEST(GradeCli, anImageDrawnWithAnotherPatternThanPromisedFails) {
    const TempDir dir;
    const std::string image = (dir / "grid.png").string();
    ASSERT_EQ(run_raster({"render", kCorpus + "teapot.yaml", "--samples", "4", "--pattern", "grid", "-o", image}).code, 0);
    const CliRun promised = run_raster({"grade", kCorpus + "teapot.yaml", image, "--samples", "4"});
    EXPECT_EQ(promised.code, 1) << promised.out << promised.err;
    EXPECT_EQ(promised.out.rfind("FAIL: ", 0), 0u) << promised.out;
    EXPECT_EQ(run_raster({"grade", kCorpus + "teapot.yaml", image, "--samples", "4", "--pattern", "grid"}).code, 0);
}

TEST(GradeCli, badInputExitsTwoNamingTheFile) {
    const TempDir dir;
    const CliRun missing = run_raster({"grade", kCorpus + "teapot.yaml", (dir / "none.png").string()});
    EXPECT_EQ(missing.code, 2);
    EXPECT_NE(missing.err.find("none.png"), std::string::npos) << missing.err;
    dir.write("text.png", "not an image");
    const CliRun garbage = run_raster({"grade", kCorpus + "teapot.yaml", (dir / "text.png").string()});
    EXPECT_EQ(garbage.code, 2);
    EXPECT_NE(garbage.err.find("text.png: not a PNG or PPM image"), std::string::npos) << garbage.err;
    const std::string small = (dir / "small.png").string();
    ASSERT_EQ(run_raster({"render", kCorpus + "single_triangle.yaml", "-o", small}).code, 0);
    const CliRun sized = run_raster({"grade", kCorpus + "teapot.yaml", small});
    EXPECT_EQ(sized.code, 2);
    EXPECT_NE(sized.err.find("the image is 320 x 240, the scene"), std::string::npos) << sized.err;
    EXPECT_EQ(run_raster({"grade", kCorpus + "teapot.yaml"}).code, 2) << "the image is required";
}

}  // namespace
}  // namespace raster::cli
