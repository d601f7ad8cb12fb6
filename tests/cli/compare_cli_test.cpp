// `raster compare`: the summary, the JSON fields, the diff map, and the exit codes 0, 1, 2 and 3.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "tests/support/cli_run.h"
#include <nlohmann/json.hpp>

#include "apps/cli.h"

namespace raster::cli {
namespace {

namespace fs = std::filesystem;

const std::string kCorpus = std::string(RASTER_SOURCE_DIR) + "/corpus/scenes/";

using test_support::CliRun;
using test_support::run_raster;

fs::path fresh_dir(const std::string& name) {
    const fs::path dir = fs::temp_directory_path() / ("raster_compare_cli_" + name + "_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

TEST(CompareCli, writesTheJsonAndTheDiffMapAndExitsZeroWithoutGenuineDisagreements) {
    const fs::path dir = fresh_dir("ok");
    const CliRun r = run_raster({"compare", kCorpus + "single_triangle.yaml", "--samples", "4", "--json",
                          (dir / "out.json").string(), "--diff", (dir / "diff.png").string()});
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.out.find("genuine    0"), std::string::npos) << r.out;
    std::ifstream file(dir / "out.json");
    const nlohmann::json json = nlohmann::json::parse(file);
    for (const char* key : {"scene", "samples", "agree", "ambiguous", "genuine", "genuine_total", "max_color_error",
                            "raster_ms", "oracle_ms"})
        EXPECT_TRUE(json.contains(key)) << key;
    for (const char* key : {"edge_band", "depth_tie", "clip_boundary", "facing"}) EXPECT_TRUE(json["ambiguous"].contains(key)) << key;
    for (const char* key : {"visibility", "barycentrics", "depth", "color"}) EXPECT_TRUE(json["genuine"].contains(key)) << key;
    EXPECT_EQ(json["samples"], 4);
    EXPECT_EQ(json["genuine_total"], 0);
    EXPECT_EQ(json["agree"].get<uint64_t>() + json["ambiguous_total"].get<uint64_t>(), 320u * 240u * 4u);
    EXPECT_GT(fs::file_size(dir / "diff.png"), 100u);
    fs::remove_all(dir);
}

// `--junit` on both commands: a file the common JUnit schema accepts (tests/support/junit.xsd), one case per scene.
TEST(CompareCli, compareAndReportWriteJunitXmlWithACasePerScene) {
    const fs::path dir = fresh_dir("junit");
    const CliRun compare = run_raster({"compare", kCorpus + "single_triangle.yaml", "--junit", (dir / "compare.xml").string()});
    ASSERT_EQ(compare.code, 0) << compare.err;
    const CliRun report = run_raster({"report", kCorpus + "single_triangle.yaml", kCorpus + "flat_cube.yaml", "-o",
                                      (dir / "report").string(), "--junit", (dir / "report.xml").string()});
    ASSERT_EQ(report.code, 0) << report.err;
    const std::string schema = std::string(RASTER_SOURCE_DIR) + "/tests/support/junit.xsd";
    for (const char* name : {"compare.xml", "report.xml"}) {
        const std::string command =
            "xmllint --noout --schema '" + schema + "' '" + (dir / name).string() + "' > /dev/null 2>&1";
        EXPECT_EQ(std::system(command.c_str()), 0) << name;
    }
    std::stringstream compare_xml, report_xml;
    compare_xml << std::ifstream(dir / "compare.xml").rdbuf();
    report_xml << std::ifstream(dir / "report.xml").rdbuf();
    EXPECT_NE(compare_xml.str().find("tests=\"1\" failures=\"0\""), std::string::npos) << compare_xml.str();
    EXPECT_NE(report_xml.str().find("tests=\"2\" failures=\"0\""), std::string::npos) << report_xml.str();
    EXPECT_NE(report_xml.str().find("name=\"flat_cube.yaml, "), std::string::npos) << report_xml.str();
    fs::remove_all(dir);
}

TEST(CompareCli, badInputExitsTwoAndWritesNothing) {
    const fs::path dir = fresh_dir("bad");
    EXPECT_EQ(run_raster({"compare", (dir / "missing.yaml").string(), "--json", (dir / "out.json").string()}).code, 2);
    const CliRun bad_samples = run_raster({"compare", kCorpus + "single_triangle.yaml", "--samples", "3", "--json",
                                    (dir / "out.json").string()});
    EXPECT_EQ(bad_samples.code, 2);
    EXPECT_NE(bad_samples.err.find("1, 2, 4, 8 or 16"), std::string::npos) << bad_samples.err;
    EXPECT_EQ(run_raster({"compare"}).code, 2);
    EXPECT_FALSE(fs::exists(dir / "out.json"));
    fs::remove_all(dir);
}

TEST(CompareCli, aFrameRenderCanDrawButTooLargeToCompareIsRefusedBeforeAnyWork) {
    // 2500 x 2500 at 16 samples: render's frame buffers fit its 4 GiB cap (2.8 GB), the comparison's do not.
    const fs::path dir = fresh_dir("large");
    const fs::path scene = dir / "large.yaml";
    std::ofstream(scene) << "image: {width: 2500, height: 2500}\nrender: {samples: 16}\n"
                            "meshes:\n  - {vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0]], faces: [[0, 1, 2]]}\n";
    const CliRun r = run_raster({"compare", scene.string(), "--json", (dir / "out.json").string()});
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find("MiB, over the 4096 MiB cap"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / "out.json"));
    fs::remove_all(dir);
}

TEST(CompareCli, anOutputThatCannotBeWrittenExitsThree) {
    const CliRun r = run_raster({"compare", kCorpus + "single_triangle.yaml", "--json", "/nonexistent-dir/out.json"});
    EXPECT_EQ(r.code, 3);
    EXPECT_NE(r.err.find("out.json"), std::string::npos) << r.err;
}

TEST(CompareCli, theFastOracleIsSelectable) {
    const fs::path dir = fresh_dir("fast");
    const CliRun r = run_raster({"compare", kCorpus + "interpenetrating.yaml", "--fast-oracle", "--json", (dir / "out.json").string()});
    EXPECT_EQ(r.code, 0) << r.err;
    std::ifstream file(dir / "out.json");
    EXPECT_EQ(nlohmann::json::parse(file)["oracle_mode"], "fast");
    fs::remove_all(dir);
}

}  // namespace
}  // namespace raster::cli
