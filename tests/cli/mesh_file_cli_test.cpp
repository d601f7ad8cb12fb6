// A mesh file alone on the command line: `raster render teapot.obj` draws the whole teapot inside the default
// 640 x 480 image, large, and a mesh file with nothing to draw is a clear error (exit 2) naming the file.
#include <algorithm>
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
using test_support::TempDir;

const std::filesystem::path kSource = RASTER_SOURCE_DIR;

TEST(MeshFileCli, rendersTheWholeMeshLargeInTheDefaultImage) {
    TempDir dir;
    const std::filesystem::path image = dir / "teapot.ppm";
    const auto run = run_raster({"render", (kSource / "corpus/meshes/teapot.obj").string(), "-o", image.string()});
    ASSERT_EQ(run.code, 0) << run.err;
    std::ifstream in(image, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string header = "P6\n640 480\n255\n";
    ASSERT_EQ(bytes.substr(0, header.size()), header);
    ASSERT_EQ(bytes.size(), header.size() + 640u * 480u * 3u);
    // The box of the pixels that are not the black background.
    int left = 640, right = -1, top = 480, bottom = -1;
    for (int y = 0; y < 480; ++y)
        for (int x = 0; x < 640; ++x) {
            const size_t at = header.size() + 3u * (static_cast<size_t>(y) * 640u + static_cast<size_t>(x));
            if (bytes[at] == 0 && bytes[at + 1] == 0 && bytes[at + 2] == 0) continue;
            left = std::min(left, x), right = std::max(right, x);
            top = std::min(top, y), bottom = std::max(bottom, y);
        }
    // Nothing cut off at the image's edges, and the teapot large in it: the sphere through its farthest vertex
    // spans 95% of the height, and the teapot, wider than tall, more than half the width.
    EXPECT_GT(left, 0);
    EXPECT_LT(right, 639);
    EXPECT_GT(top, 0);
    EXPECT_LT(bottom, 479);
    EXPECT_GT(right - left, 640 / 2) << "left " << left << ", right " << right;
    EXPECT_GT(bottom - top, 480 * 4 / 10) << "top " << top << ", bottom " << bottom;
}

TEST(MeshFileCli, aMeshWithNothingToDrawExitsTwoNamingTheFile) {
    TempDir dir;
    const auto mesh = dir.write("lines.obj", "v 0 0 0\nv 1 0 0\nl 1 2\n");
    const auto run = run_raster({"render", mesh.string(), "-o", (dir / "out.png").string()});
    EXPECT_EQ(run.code, 2);
    EXPECT_NE(run.err.find(mesh.string()), std::string::npos) << run.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "out.png"));
}

}  // namespace
}  // namespace raster
