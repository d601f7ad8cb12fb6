// CommandLine, the command line built once and run many times: every run behaves as a fresh `raster` on the same
// arguments (the same exit code, output, messages and files), whatever flags the runs before it set.
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "apps/cli.h"
#include "tests/support/cli_run.h"
#include "tests/support/temp_dir.h"

namespace {

using raster::test_support::CliRun;
using raster::test_support::run_raster;
using raster::test_support::TempDir;

const std::string kScene =
    "image: {width: 8, height: 6}\nrender: {samples: 1, shading: phong}\nlights: [{position: [1, 1, 4]}]\n"
    "meshes:\n  - vertices: [[-1, -1, 0], [1, -1, 0], [0, 1, 0]]\n    faces: [[0, 1, 2]]\n";

std::string read_bytes(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// Each argument list after flags that, if they leaked into the next run, would change what it does: a render with
// every settings flag set then one with none, a flag-only tradeoff then one that needs scenes, help, and errors.
std::vector<std::vector<std::string>> argument_lists(const TempDir& dir) {
    const std::string scene = dir.write("scene.yaml", kScene).string();
    const std::string out = (dir / "out").string();
    return {
        {"render", scene, "-o", out + "/flags.png", "--samples", "4", "--pattern", "grid", "--msaa", "--shading",
         "flat", "--snap-bits", "4", "--cull", "back", "--edges", "float", "--interpolation", "affine",
         "--depth-format", "fixed24", "--clipping", "guard-band", "--hierarchical-z", "off", "--alpha", "--depth-out",
         out + "/depth.png"},
        {"render", scene, "-o", out + "/plain.png"},
        {"tradeoff", "--list-modes"},
        {"tradeoff", "-o", out + "/tradeoff"},
        {"render", "--help"},
        {"compare", scene, "--samples", "3"},
        {"compare"},
        {"report", "-o", out + "/report", "--samples", "0"},
        {"balboa", "-hw"},
        {"render"},
        {"--help"},
    };
}

TEST(CommandLine, runsEveryArgumentListAsAFreshCommandLineWould) {
    const TempDir reused_dir, fresh_dir;
    std::filesystem::create_directories(reused_dir / "out");
    std::filesystem::create_directories(fresh_dir / "out");
    const auto reused_lists = argument_lists(reused_dir), fresh_lists = argument_lists(fresh_dir);
    raster::cli::CommandLine command_line;
    for (size_t i = 0; i < reused_lists.size(); ++i) {
        std::vector<std::string> args = reused_lists[i];
        args.insert(args.begin(), "raster");
        std::ostringstream out, err;
        const int code = command_line.run(args, out, err);
        const CliRun fresh = run_raster(fresh_lists[i]);
        SCOPED_TRACE("argument list " + std::to_string(i) + ": " + reused_lists[i][0]);
        EXPECT_EQ(code, fresh.code);
        // Messages name the files, whose folders differ: compare them with the folder names swapped.
        std::string reused_err = err.str(), reused_out = out.str();
        for (std::string* text : {&reused_err, &reused_out})
            for (size_t at; (at = text->find(reused_dir.path().string())) != std::string::npos;)
                text->replace(at, reused_dir.path().string().size(), fresh_dir.path().string());
        EXPECT_EQ(reused_out, fresh.out);
        EXPECT_EQ(reused_err, fresh.err);
    }
    for (const std::string name : {"flags.png", "depth.png", "plain.png"}) {
        EXPECT_TRUE(std::filesystem::exists(reused_dir / "out" / name)) << name;
        EXPECT_EQ(read_bytes(reused_dir / "out" / name), read_bytes(fresh_dir / "out" / name)) << name;
    }
}

}  // namespace
