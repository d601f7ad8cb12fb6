// Seed 001's command line, `raster balboa`: scene files for every part, default output names, bad input, --help.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/support/seed_test_support.h"

namespace raster {
namespace {

using namespace seed_test;

TEST(Seed001, renderReadsTheSameSceneAsBalboaAndParts22And23TakeSceneFiles) {
    TempDir dir;
    const std::string scene = corpus("seeds/001/two_shapes.json").string();
    ASSERT_EQ(run_raster({"balboa", "-hw", "2_4", scene, "-o", (dir / "b.ppm").string()}).status, 0);
    ASSERT_EQ(run_raster({"render", scene, "-o", (dir / "r.ppm").string()}).status, 0);
    ASSERT_EQ(run_raster({"balboa", "-hw", "2_3", scene, "-o", (dir / "b3.ppm").string()}).status, 0);
    EXPECT_EQ(read_text(dir / "b.ppm"), read_text(dir / "r.ppm"));
    EXPECT_EQ(read_text(dir / "b.ppm"), read_text(dir / "b3.ppm"));
}

TEST(Seed001, defaultOutputNamesFollowTheDocumentsSubmissionNames) {
    TempDir dir;
    const fs::path here = fs::current_path();
    fs::current_path(dir.path());
    const CliResult triangle = run_raster({"balboa", "-hw", "2_1", "-p0", "0", "0", "-1", "-p1", "1", "0", "-1", "-p2",
                                           "0", "1", "-1", "-color", "1", "1", "1"});
    const CliResult scene = run_raster({"balboa", "-hw", "2_4", corpus("seeds/001/tetrahedron.json").string()});
    fs::current_path(here);
    EXPECT_EQ(triangle.status, 0) << triangle.err;
    EXPECT_EQ(scene.status, 0) << scene.err;
    EXPECT_TRUE(fs::exists(dir / "hw_2_1.png"));
    EXPECT_TRUE(fs::exists(dir / "hw_2_4_tetrahedron.png"));
}

struct BadCommand {
    std::vector<std::string> args;
    std::string message;
};

TEST(Seed001, badCommandLinesExitTwoWithAClearMessageAndWriteNothing) {
    const std::vector<std::string> triangle = {"-hw", "2_1", "-p0", "-1", "-1", "-3", "-p1", "0", "1", "-3",
                                               "-p2", "1", "-1", "-3", "-color", "0.7", "0.3", "0.4"};
    auto with = [&](std::vector<std::string> extra) {
        std::vector<std::string> args = triangle;
        args.insert(args.end(), extra.begin(), extra.end());
        return args;
    };
    const std::vector<BadCommand> cases = {
        {{"-hw", "2_1", "-p0", "1", "2"}, "-p0 needs 3 numbers (X Y Z), got 2"},
        {{"-hw", "2_1", "-p0", "1", "2", "-p1", "0", "0", "-1"}, "-p0 needs 3 numbers (X Y Z), got 2"},
        {{"-hw", "2_1", "-p0", "1", "x", "3"}, "-p0: 'x' is not a number"},
        {with({"-q"}), "unknown flag '-q'"},
        {with({"-s"}), "-s needs 1 number"},
        {with({"-znear", "0"}), "z_near must be > 0"},
        {with({"-s", "-2"}), "s must be a positive number"},
        {with({"-color", "1", "1", "1"}), "-color is given twice"},
        {{"-hw", "2_1", "-p0", "0", "0", "-1", "-p1", "1", "0", "-1", "-color", "1", "1", "1"}, "needs -p2"},
        {{"-p0", "0", "0", "-1"}, "missing -hw"},
        {{"-hw", "3_1"}, "2_1, 2_2, 2_3 and 2_4"},
        {{"-hw", "2_2", "-s", "1", "-znear", "1e-6", "-scene_id", "0"}, "-scene_id"},
        {{"-hw", "2_4"}, "needs a scene file"},
        {with({"scene.json"}), "takes no scene file"},
        {{"-hw", "2_4", "a.json", "b.json"}, "unexpected argument 'b.json'"},
        {{"-hw", "2_4", "missing.json"}, "missing.json"},
    };
    for (const BadCommand& bad : cases) {
        TempDir dir;
        std::vector<std::string> args = {"balboa"};
        args.insert(args.end(), bad.args.begin(), bad.args.end());
        args.insert(args.end(), {"-o", (dir / "out.png").string()});
        const CliResult result = run_raster(args);
        EXPECT_EQ(result.status, 2) << bad.message;
        EXPECT_TRUE(contains(result.err, "raster balboa: error:")) << bad.message;
        EXPECT_TRUE(contains(result.err, bad.message));
        EXPECT_FALSE(fs::exists(dir / "out.png")) << bad.message;
    }
}

TEST(Seed001, helpListsBalboasFlags) {
    for (const char* flag : {"-h", "--help"}) {
        const CliResult result = run_raster({"balboa", flag});
        EXPECT_EQ(result.status, 0);
        for (const char* word : {"-hw", "2_1", "2_4", "-p0", "-color", "-s S", "-znear", "-o", "640 x 480", "128"})
            EXPECT_TRUE(contains(result.out, word)) << flag;
    }
}

}  // namespace
}  // namespace raster
