// What a scene file asks of `raster render` besides its scene: nothing for raster's own format, the output and the
// task's image for a seed 000 config, and a self-check for its transform-test task, all from one parse.
#include "raster/compat/scene_loader.h"

#include <sstream>

#include <gtest/gtest.h>

namespace raster {
namespace {

const std::filesystem::path kSource = RASTER_SOURCE_DIR;

TEST(SceneFile, ofRastersOwnFormatAsksForNothingButItsScene) {
    const SceneFile file = load_scene_file(kSource / "corpus/scenes/teapot.yaml");
    EXPECT_EQ(file.format, SceneFormat::raster);
    EXPECT_TRUE(file.request.output.empty());
    EXPECT_FALSE(file.request.depth_image);
    EXPECT_FALSE(file.request.self_check);
    EXPECT_FALSE(file.scene.meshes.empty());
}

TEST(SceneFile, ofASeed000ConfigNamesItsOutputAndWhetherItIsTheDepthImage) {
    const SceneFile shading = load_scene_file(kSource / "corpus/seeds/000/test-shading.yaml");
    EXPECT_EQ(shading.format, SceneFormat::seed000);
    EXPECT_EQ(shading.request.output.filename(), "output.png");
    EXPECT_FALSE(shading.request.depth_image);
    EXPECT_FALSE(shading.request.self_check);
    const SceneFile depth = load_scene_file(kSource / "corpus/seeds/000/test-shading-depth.yaml");
    EXPECT_EQ(depth.request.output.filename(), "output.png");
    EXPECT_TRUE(depth.request.depth_image);
}

TEST(SceneFile, ofASeed000TransformTestRunsItsCheckInsteadOfAnImage) {
    const SceneFile file = load_scene_file(kSource / "corpus/seeds/000/test-transform-test.yaml");
    ASSERT_TRUE(file.request.self_check);
    EXPECT_TRUE(file.request.output.empty());
    std::ostringstream printed;
    EXPECT_TRUE(file.request.self_check(printed));
    EXPECT_NE(printed.str().find("match"), std::string::npos) << printed.str();
}

}  // namespace
}  // namespace raster
