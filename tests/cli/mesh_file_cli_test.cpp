// A mesh file alone on the command line: `raster render teapot.obj` draws the whole teapot inside the default
// 640 x 480 image, large, the same bytes at any power-of-two size, and a mesh file with nothing to draw is a clear
// error (exit 2) naming the file.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
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
    // Nothing cut off at the image's edges, and the teapot large in it. Its sphere through the farthest vertex is
    // framed to 1/1.05 of the height; the teapot, wider than tall, spans more than half the width and, seen from
    // 30 degrees up, 48% of the height as rendered: 40% is a floor well above a mesh framed small, well below that.
    EXPECT_GT(left, 0);
    EXPECT_LT(right, 639);
    EXPECT_GT(top, 0);
    EXPECT_LT(bottom, 479);
    EXPECT_GT(right - left, 640 / 2) << "left " << left << ", right " << right;
    EXPECT_GT(bottom - top, 480 * 4 / 10) << "top " << top << ", bottom " << bottom;
}

// A mesh scaled by a power of two, with its framing camera and light, is the same scene at another size: every
// product and quotient of the pipeline scales exactly, so the bytes must be the same. At 2^40 and 2^60 the faces'
// cross products pass float's squared range (before unit_vector.h, the teapot went unlit), at 2^-40 and 2^-60 they
// fall under it.
TEST(MeshFileCli, aMeshScaledByAPowerOfTwoRendersTheSameBytes) {
    TempDir dir;
    const auto render = [&](const std::filesystem::path& mesh, const std::string& name) {
        const std::filesystem::path image = dir / name;
        const auto run = run_raster({"render", mesh.string(), "-o", image.string()});
        EXPECT_EQ(run.code, 0) << run.err;
        std::ifstream in(image, std::ios::binary);
        return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    };
    const std::filesystem::path teapot = kSource / "corpus/meshes/teapot.obj";
    const std::string unit = render(teapot, "unit.ppm");
    ASSERT_GT(unit.size(), 640u * 480u * 3u);
    std::ifstream in(teapot);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    for (const int exponent : {40, -40, 60, -60}) {
        std::istringstream lines(text);
        std::ostringstream scaled;
        scaled.precision(9);  // a float's value, exactly
        for (std::string line; std::getline(lines, line);) {
            if (line.rfind("v ", 0) != 0) {
                scaled << line << '\n';
                continue;
            }
            std::istringstream words(line.substr(2));
            float x, y, z;
            words >> x >> y >> z;
            scaled << "v " << std::ldexp(x, exponent) << ' ' << std::ldexp(y, exponent) << ' ' << std::ldexp(z, exponent)
                   << '\n';
        }
        const auto mesh = dir.write("teapot" + std::to_string(exponent) + ".obj", scaled.str());
        EXPECT_TRUE(render(mesh, "scaled.ppm") == unit) << "2^" << exponent;
    }
}

TEST(MeshFileCli, aMeshWithNothingToDrawExitsTwoNamingTheFile) {
    TempDir dir;
    const auto mesh = dir.write("lines.obj", "v 0 0 0\nv 1 0 0\nl 1 2\n");
    const auto run = run_raster({"render", mesh.string(), "-o", (dir / "out.png").string()});
    EXPECT_EQ(run.code, 2);
    EXPECT_NE(run.err.find(mesh.string()), std::string::npos) << run.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "out.png"));
}

// What assimp and viewers draw, raster draws: an OBJ whose texture is missing renders untextured with a warning
// naming the MTL line, and --strict makes it the error it was before (exit 2, nothing written).
TEST(MeshFileCli, anObjWithAMissingTextureRendersWithAWarningUnlessStrict) {
    TempDir dir;
    dir.write("quad.obj", "mtllib quad.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nusemtl wood\nf 1/1 2/2 3/3\n");
    dir.write("quad.mtl", "newmtl wood\nmap_Kd .\\Texture.jpg\n");
    testing::internal::CaptureStderr();  // the loaders warn on the process's stderr
    const auto lenient = run_raster({"render", (dir / "quad.obj").string(), "-o", (dir / "out.png").string()});
    const std::string warnings = testing::internal::GetCapturedStderr();
    EXPECT_EQ(lenient.code, 0) << lenient.err;
    EXPECT_NE(warnings.find("quad.mtl:2: warning: map_Kd '.\\Texture.jpg'"), std::string::npos) << warnings;
    EXPECT_NE(warnings.find("drawn untextured"), std::string::npos) << warnings;
    EXPECT_TRUE(std::filesystem::exists(dir / "out.png"));

    const auto strict = run_raster({"render", (dir / "quad.obj").string(), "--strict", "-o", (dir / "strict.png").string()});
    EXPECT_EQ(strict.code, 2);
    EXPECT_NE(strict.err.find("quad.mtl:2"), std::string::npos) << strict.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "strict.png"));
}

}  // namespace
}  // namespace raster
