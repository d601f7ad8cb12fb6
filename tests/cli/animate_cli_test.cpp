// Animated scenes on the command line: `raster animate` writes one PNG a frame at the frame rate, each the same
// bytes as `raster render --time` of its instant; `--time` poses glTF and raster scenes alike; a scene without
// animation is refused by both (exit 2).
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <gtest/gtest.h>

#include "tests/support/cli_run.h"
#include "tests/support/temp_dir.h"

namespace raster {
namespace {

using test_support::run_raster;
using test_support::read_file;
using test_support::TempDir;

const std::filesystem::path kSource = RASTER_SOURCE_DIR;

TEST(AnimateCli, writesAFrameForEachInstantTheSameAsRenderAtThatTime) {
    TempDir dir;
    const std::string scene = (kSource / "corpus/scenes/spinning_teapot.yaml").string();
    const auto run = run_raster({"animate", scene, "--fps", "4", "--duration", "0.5", "--threads", "1", "-o",
                                 (dir / "frames").string(), "--samples", "1"});
    ASSERT_EQ(run.code, 0) << run.err;
    // 0, 0.25 and 0.5 s: three frames, and no fourth.
    ASSERT_TRUE(std::filesystem::exists(dir / "frames/frame_0002.png"));
    EXPECT_FALSE(std::filesystem::exists(dir / "frames/frame_0003.png"));
    for (const auto& [frame, time] : {std::pair{"frame_0000.png", "0"}, std::pair{"frame_0002.png", "0.5"}}) {
        const auto render = run_raster({"render", scene, "--time", time, "--threads", "1", "--samples", "1", "-o",
                                        (dir / ("render_" + std::string(time) + ".png")).string()});
        ASSERT_EQ(render.code, 0) << render.err;
        EXPECT_EQ(read_file(dir / "frames" / frame), read_file(dir / ("render_" + std::string(time) + ".png"))) << frame;
    }
    // The teapot moves: the frames differ.
    EXPECT_NE(read_file(dir / "frames/frame_0000.png"), read_file(dir / "frames/frame_0001.png"));
}

// Keys at 0 and 0.7 s (0.699999988 as a float) at 10 fps: 8 frames, the last at the last key, not 7. A span too
// long for the frame cap is an error, not an empty folder.
TEST(AnimateCli, theSpanCountsItsLastKeyAndATooLongOneIsRefused) {
    TempDir dir;
    const std::string shape =
        "image: {width: 32, height: 24}\n"
        "shapes: {tri: {vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0]], faces: [[0, 1, 2]]}}\n";
    const auto scene = dir.write("keys.yaml", shape + "nodes: [{shape: tri, keyframes: [{time: 0, scale: 1}, {time: 0.7, scale: 2}]}]\n");
    const auto run = run_raster({"animate", scene.string(), "--fps", "10", "-o", (dir / "frames").string()});
    ASSERT_EQ(run.code, 0) << run.err;
    EXPECT_TRUE(std::filesystem::exists(dir / "frames/frame_0007.png"));
    EXPECT_FALSE(std::filesystem::exists(dir / "frames/frame_0008.png"));

    const auto long_scene = dir.write("long.yaml", shape + "nodes: [{shape: tri, keyframes: [{time: 0, scale: 1}, {time: 1e10, scale: 2}]}]\n");
    const auto refused = run_raster({"animate", long_scene.string(), "-o", (dir / "long").string()});
    EXPECT_EQ(refused.code, 2);
    EXPECT_NE(refused.err.find("raster animate writes at most 100000"), std::string::npos) << refused.err;
}

TEST(AnimateCli, aGltfAnimationPosesAtTheTimeAsked) {
    TempDir dir;
    const std::string model = (kSource / "corpus/gltf/animated_box.gltf").string();
    const auto early = run_raster({"render", model, "--time", "0.5", "-o", (dir / "early.png").string()});
    const auto late = run_raster({"render", model, "--time", "2.5", "-o", (dir / "late.png").string()});
    ASSERT_EQ(early.code, 0) << early.err;
    ASSERT_EQ(late.code, 0) << late.err;
    EXPECT_NE(read_file(dir / "early.png"), read_file(dir / "late.png"));
}

TEST(AnimateCli, aSceneWithoutAnimationIsRefused) {
    TempDir dir;
    const std::string scene = (kSource / "corpus/scenes/single_triangle.yaml").string();
    const auto animate = run_raster({"animate", scene, "-o", (dir / "frames").string()});
    EXPECT_EQ(animate.code, 2);
    EXPECT_NE(animate.err.find("the scene has no animation"), std::string::npos) << animate.err;
    const auto render = run_raster({"render", scene, "--time", "1", "-o", (dir / "x.png").string()});
    EXPECT_EQ(render.code, 2);
    EXPECT_NE(render.err.find("--time: the scene has no animation to pose"), std::string::npos) << render.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "x.png"));
}

}  // namespace
}  // namespace raster
