// A glTF file on the command line: `raster render model.gltf` and `model.glb` draw it at its camera's aspect ratio
// and where its nodes put it, the same bytes whether its buffers and images are files, data URIs or GLB chunks; a hostile file is an error (exit 2) naming the file and the JSON path of the problem,
// and one that names a file outside its folder is refused without reading it.
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/support/cli_run.h"
#include "tests/support/temp_dir.h"

namespace raster {
namespace {

using test_support::run_raster;
using test_support::read_file;
using test_support::TempDir;

const std::filesystem::path kSource = RASTER_SOURCE_DIR;

TEST(GltfCli, rendersAModelAtItsCamerasAspectRatio) {
    TempDir dir;
    const std::filesystem::path image = dir / "boxes.ppm";
    const auto run = run_raster({"render", (kSource / "corpus/gltf/instanced_boxes.gltf").string(), "-o", image.string()});
    ASSERT_EQ(run.code, 0) << run.err;
    // aspectRatio 1.5 at the default height of 480.
    EXPECT_EQ(read_file(image).substr(0, 15), "P6\n720 480\n255\n");
}

TEST(GltfCli, aGlbWithItsEmbeddedTextureRenders) {
    TempDir dir;
    const std::filesystem::path image = dir / "quad.ppm";
    const auto run = run_raster({"render", (kSource / "corpus/gltf/textured_quad.glb").string(), "-o", image.string()});
    ASSERT_EQ(run.code, 0) << run.err;
    const std::string bytes = read_file(image);
    ASSERT_EQ(bytes.substr(0, 15), "P6\n640 480\n255\n");
    // The framed quad covers the image's centre, which is neither the black background nor one flat colour: the
    // checker's squares show through.
    size_t distinct = 0;
    std::string seen;
    for (int x = 280; x < 360; ++x) {
        const std::string pixel = bytes.substr(15 + 3 * (240u * 640u + static_cast<size_t>(x)), 3);
        if (seen.find(pixel) == std::string::npos) seen += pixel, ++distinct;
    }
    EXPECT_GE(distinct, 2u);
}

TEST(GltfCli, aGltfWithFilesAGlbAndAnEmbeddedCopyOfOneModelRenderTheSameBytes) {
    // corpus/gltf/alpha_cutouts: data URIs (.gltf), a buffer and images in files beside it (_external.gltf), and a
    // GLB with its images in the binary chunk; animated, textured with alpha, two cameras.
    TempDir dir;
    for (const std::vector<std::string>& flags :
         {std::vector<std::string>{"--time", "0.6", "--samples", "4"}, std::vector<std::string>{"--camera", "1", "--time", "1.7"}}) {
        std::vector<std::string> images;
        for (const char* model : {"alpha_cutouts.gltf", "alpha_cutouts_external.gltf", "alpha_cutouts.glb"}) {
            const std::filesystem::path image = dir / (std::string(model) + ".png");
            std::vector<std::string> args = {"render", (kSource / "corpus/gltf" / model).string(), "-o", image.string()};
            args.insert(args.end(), flags.begin(), flags.end());
            const auto run = run_raster(args);
            ASSERT_EQ(run.code, 0) << model << ": " << run.err;
            images.push_back(read_file(image));
        }
        ASSERT_GT(images[0].size(), 1000u);
        EXPECT_TRUE(images[1] == images[0]) << "the model with its files beside it renders other bytes, " << flags[0];
        EXPECT_TRUE(images[2] == images[0]) << "the GLB renders other bytes, " << flags[0];
    }
}

TEST(GltfCli, aHostileFileIsAnErrorNamingTheFileAndTheJsonPath) {
    TempDir dir;
    std::string text = read_file(kSource / "corpus/gltf/instanced_boxes.gltf");
    const std::string count = "\"count\": 24";
    ASSERT_NE(text.find(count), std::string::npos);
    text.replace(text.find(count), count.size(), "\"count\": 2400");
    const std::filesystem::path model = dir.write("model.gltf", text);
    dir.write("instanced_boxes.bin", read_file(kSource / "corpus/gltf/instanced_boxes.bin"));
    const auto run = run_raster({"render", model.string(), "-o", (dir / "out.png").string()});
    EXPECT_EQ(run.code, 2);
    EXPECT_NE(run.err.find("model.gltf"), std::string::npos) << run.err;
    EXPECT_NE(run.err.find("/accessors/0/count: 2400 elements"), std::string::npos) << run.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "out.png"));
}

TEST(GltfCli, aBufferOutsideTheModelsFolderIsRefused) {
    TempDir dir;
    dir.write("secret.bin", read_file(kSource / "corpus/gltf/instanced_boxes.bin"));
    std::string text = read_file(kSource / "corpus/gltf/instanced_boxes.gltf");
    const std::string uri = "\"uri\": \"instanced_boxes.bin\"";
    ASSERT_NE(text.find(uri), std::string::npos);
    text.replace(text.find(uri), uri.size(), "\"uri\": \"../secret.bin\"");
    const std::filesystem::path model = dir.write("models/model.gltf", text);
    const auto run = run_raster({"render", model.string(), "-o", (dir / "out.png").string()});
    EXPECT_EQ(run.code, 2);
    EXPECT_NE(run.err.find("'../secret.bin' is not a path inside the model's folder"), std::string::npos) << run.err;
}

}  // namespace
}  // namespace raster
