// Choosing among a glTF file's cameras: camera nodes are counted depth first, children in order, each named by its
// node (or "camera N"); the chosen one is drawn from, with its own aspect; one that is not there is refused with
// the list; a scene format with one camera refuses any choice but the first.
#include <gtest/gtest.h>

#include "raster/compat/scene_loader.h"
#include "raster/core/errors.h"
#include "raster/gltf/gltf_scene.h"
#include "tests/support/gltf_builder.h"

namespace raster {
namespace {

using test_support::GltfBuilder;
using test_support::no_files;

// A triangle, and three camera nodes: "front" (a root), a nameless one (the child of a root group) and "top" (a root
// after the group). Walked depth first: front, the child, top.
GltfBuilder three_cameras() {
    GltfBuilder b = GltfBuilder::one_triangle();
    b.document["cameras"] = {{{"type", "perspective"}, {"perspective", {{"yfov", 0.5}, {"znear", 0.1}, {"zfar", 50}}}},
                             {{"type", "perspective"},
                              {"perspective", {{"yfov", 0.9}, {"znear", 0.2}, {"zfar", 60}, {"aspectRatio", 1.0}}}}};
    b.node({{"name", "front"}, {"camera", 0}, {"translation", {0, 0, 5}}});
    const int child = b.node({{"camera", 1}, {"translation", {1, 2, 3}}}, false);
    b.node({{"name", "group"}, {"translation", {10, 0, 0}}, {"children", {child}}});
    b.node({{"name", "top"}, {"camera", 0}, {"translation", {0, 8, 0}}, {"rotation", {-0.7071068, 0, 0, 0.7071068}}});
    return b;
}

Scene read_with_camera(const GltfBuilder& b, int camera, GltfSceneParts* parts = nullptr) {
    Scene scene;
    const GltfSceneParts got = read_gltf_scene(b.text(), "model.gltf", no_files(), scene, camera);
    if (parts) *parts = got;
    return scene;
}

TEST(GltfCameras, cameraNodesAreCountedDepthFirstAndNamedByTheirNodes) {
    GltfSceneParts parts;
    const Scene first = read_with_camera(three_cameras(), 0, &parts);
    EXPECT_EQ(parts.cameras, (std::vector<std::string>{"front", "camera 1", "top"}));
    EXPECT_EQ(first.camera.eye, glm::vec3(0, 0, 5));
    EXPECT_EQ(first.settings.width, 640);  // no aspect ratio: raster's default image
    const Scene child = read_with_camera(three_cameras(), 1);
    EXPECT_EQ(child.camera.eye, glm::vec3(11, 2, 3));  // its own translation after its group's
    EXPECT_NEAR(child.camera.fov_y_degrees, 0.9 * 180.0 / 3.14159265358979323846, 1e-4);
    EXPECT_EQ(child.settings.width, 480);  // its aspect ratio of 1
    const Scene top = read_with_camera(three_cameras(), 2);
    EXPECT_NEAR(top.camera.eye.y, 8.0f, 1e-6);
    EXPECT_NEAR(glm::normalize(top.camera.target - top.camera.eye).y, -1.0f, 1e-6);  // turned to look down
}

TEST(GltfCameras, aCameraTheFileDoesNotPlaceIsRefusedWithTheList) {
    try {
        read_with_camera(three_cameras(), 3);
        FAIL() << "camera 3 was read";
    } catch (const InputError& e) {
        EXPECT_EQ(e.message(), "/nodes: there is no camera 3 to draw from; the scene places 3 cameras: 0 'front', "
                               "1 'camera 1', 2 'top'");
    }
    EXPECT_THROW(read_with_camera(GltfBuilder::one_triangle(), 1), InputError);  // none at all
}

TEST(GltfCameras, aSceneFormatWithOneCameraRefusesAnyOtherChoice) {
    for (const char* file : {"/corpus/scenes/teapot.yaml", "/corpus/meshes/teapot.obj"}) {
        const std::string path = std::string(RASTER_SOURCE_DIR) + file;
        EXPECT_NO_THROW(load_scene_file(path, {false, 0})) << file;
        try {
            load_scene_file(path, {false, 1});
            ADD_FAILURE() << "a camera was chosen in " << file;
        } catch (const InputError& e) {
            EXPECT_EQ(e.message(), "camera 1 asked for: only a glTF file places cameras to choose from") << file;
        }
    }
}

}  // namespace
}  // namespace raster
