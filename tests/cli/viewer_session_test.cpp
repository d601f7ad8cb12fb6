// `raster view`'s frames in-process: the first frame is `raster render`'s image, a request changes only its own
// frame, bad frames are refused, the filter reaches textured materials, a check is the comparison of its frame, and
// the log records what was sent. PNG bytes
// are compared with ==, so that a failure does not print them.
#include "apps/viewer_session.h"

#include <gtest/gtest.h>

#include "harness/comparison/comparison_output.h"
#include "oracle/compare/diff_map.h"
#include "raster/compat/scene_loader.h"
#include "raster/image/image.h"
#include "raster/scene/validation.h"
#include "raster/frame/render.h"
#include "raster/transform/scene_pose.h"

namespace raster::cli {
namespace {

const std::string kScenes = std::string(RASTER_SOURCE_DIR) + "/corpus/scenes/";

RenderOptions frame_options() {
    RenderOptions options;
    options.keep_visibility = false;
    return options;
}

ViewRequest shaded(ShadingMode shading) {
    ViewRequest request;
    request.shading = shading;
    return request;
}

// A checkered floor seen at a grazing angle, where the filters disagree.
Scene checkered_floor() {
    return parse_scene("image: {width: 64, height: 48}\n"
                       "camera: {eye: [0, 1, 4], target: [0, 0, -4], fov: 50}\n"
                       "render: {shading: unlit}\n"
                       "meshes:\n"
                       "  - vertices: [[-8, 0, 4], [8, 0, 4], [8, 0, -20], [-8, 0, -20]]\n"
                       "    faces: [[0, 1, 2], [0, 2, 3]]\n"
                       "    uvs: [[0, 0], [16, 0], [16, 24], [0, 24]]\n"
                       "    material: {texture: ../textures/checker.png, filter: nearest}\n",
                       kScenes + "checkered_floor.yaml");
}

TEST(ViewerSession, theFirstFrameIsWhatRasterRenderWrites) {
    const Scene scene = load_scene(kScenes + "teapot.yaml");
    const std::vector<uint8_t> rendered = encode_image(render(scene, frame_options()).image, ImageFormat::png);
    ViewerSession session(scene, frame_options());
    const ViewerFrame frame = session.render({});
    EXPECT_TRUE(frame.png == std::string(rendered.begin(), rendered.end()));
    EXPECT_EQ(frame.record.png_fnv1a, fnv1a_64(frame.png));
    EXPECT_EQ(frame.record.shading, ShadingMode::blinn_phong);
    EXPECT_EQ(frame.record.filter, "scene");
    EXPECT_EQ(frame.record.eye, scene.camera.eye);
}

TEST(ViewerSession, eachRequestStartsFromTheSceneAsLoaded) {
    ViewerSession session(load_scene(kScenes + "teapot.yaml"), frame_options());
    const ViewerFrame first = session.render({});
    const ViewerFrame flat = session.render(shaded(ShadingMode::flat));
    ViewRequest orbited;
    orbited.yaw_degrees = 30.0;
    orbited.distance = 1.5;
    const ViewerFrame moved = session.render(orbited);
    const ViewerFrame again = session.render({});
    EXPECT_FALSE(flat.png == first.png);
    EXPECT_FALSE(moved.png == first.png);
    EXPECT_EQ(moved.record.shading, ShadingMode::blinn_phong);  // the flat request did not stay
    EXPECT_TRUE(again.png == first.png);                         // nor did the orbit
    EXPECT_EQ(again.record.eye, first.record.eye);
    EXPECT_EQ(again.record.index, 3u);
}

TEST(ViewerSession, everyShadingModeGivesItsOwnImage) {
    ViewerSession session(load_scene(kScenes + "teapot.yaml"), frame_options());
    std::set<std::string> images;
    for (const ShadingMode mode : {ShadingMode::unlit, ShadingMode::flat, ShadingMode::gouraud, ShadingMode::phong,
                                   ShadingMode::blinn_phong, ShadingMode::cel, ShadingMode::gooch})
        images.insert(session.render(shaded(mode)).png);
    EXPECT_EQ(images.size(), 7u);
}

TEST(ViewerSession, aFrameTheSceneCannotHaveIsRefused) {
    Scene scene = load_scene(kScenes + "single_triangle.yaml");
    scene.settings.pattern = SamplePattern::grid;
    ViewerSession session(scene, frame_options());
    ViewRequest two_samples;
    two_samples.samples = 2;  // not a square
    EXPECT_THROW(session.render(two_samples), ViewRequestError);
    two_samples.samples = 4;
    EXPECT_NO_THROW(session.render(two_samples));
    EXPECT_EQ(session.log()["frames_served"], 1);  // the refused one is not a frame
}

TEST(ViewerSession, aTimePosesTheAnimatedSceneAsRenderTimeDoesAndAStaticSceneRefusesIt) {
    const std::string spinning = kScenes + "spinning_teapot.yaml";
    ViewerSession session(load_scene(spinning), frame_options());
    for (const float time : {0.3f, 1.25f}) {
        Scene posed = load_scene(spinning);
        pose_scene(posed, time);
        const std::vector<uint8_t> rendered = encode_image(render(posed, frame_options()).image, ImageFormat::png);
        ViewRequest at;
        at.time = time;
        const ViewerFrame frame = session.render(at);
        EXPECT_TRUE(frame.png == std::string(rendered.begin(), rendered.end())) << time;
        EXPECT_EQ(frame.record.time, std::optional<double>(time));
    }
    EXPECT_TRUE(session.state()["animation"].is_object());
    EXPECT_EQ(session.state()["animation"]["end"], 2.0);
    ViewerSession still(load_scene(kScenes + "teapot.yaml"), frame_options());
    ViewRequest at;
    at.time = 1.0;
    EXPECT_THROW(still.render(at), ViewRequestError);
    EXPECT_TRUE(still.state()["animation"].is_null());
}

TEST(ViewerSession, aCameraRequestDrawsFromThatCameraAsTheFileLoadedWithItDoes) {
    const std::string model = std::string(RASTER_SOURCE_DIR) + "/corpus/gltf/alpha_cutouts.gltf";
    SceneFile file = load_scene_file(model);
    ViewerCameras cameras;
    cameras.names = file.cameras;
    int loads = 0;
    cameras.load = [&](int camera) {
        ++loads;
        return load_scene_file(model, {false, camera}).scene;
    };
    ASSERT_EQ(cameras.names, (std::vector<std::string>{"camera", "side"}));
    ViewerSession session(std::move(file.scene), frame_options(), cameras);
    const Scene side = load_scene_file(model, {false, 1}).scene;
    const std::vector<uint8_t> rendered = encode_image(render(side, frame_options()).image, ImageFormat::png);
    ViewRequest from_side;
    from_side.camera = 1;
    const ViewerFrame frame = session.render(from_side);
    EXPECT_TRUE(frame.png == std::string(rendered.begin(), rendered.end()));
    EXPECT_EQ(frame.record.camera, 1);
    EXPECT_EQ(frame.record.eye, side.camera.eye);
    session.render(from_side);
    EXPECT_EQ(loads, 1);  // each camera loaded once
    ViewRequest first;
    first.camera = 0;
    EXPECT_FALSE(session.render(first).png == frame.png);
    ViewRequest missing;
    missing.camera = 2;
    EXPECT_THROW(session.render(missing), ViewRequestError);
    EXPECT_EQ(session.state()["cameras"]["names"], nlohmann::json::array({"camera", "side"}));
}

TEST(ViewerSession, theFilterReachesEveryTexturedMaterial) {
    ViewerSession session(checkered_floor(), frame_options());
    EXPECT_EQ(session.state()["scene_settings"]["filter"], "nearest");
    EXPECT_EQ(session.state()["textured"], true);
    ViewRequest request;
    const std::string scene_own = session.render(request).png;
    request.filter = TextureFilter::nearest;
    EXPECT_TRUE(session.render(request).png == scene_own);
    request.filter = TextureFilter::trilinear;
    const ViewerFrame trilinear = session.render(request);
    EXPECT_FALSE(trilinear.png == scene_own);
    EXPECT_EQ(trilinear.record.filter, "trilinear");
    request.filter = std::nullopt;
    EXPECT_TRUE(session.render(request).png == scene_own);  // the trilinear copy left the scene as it was
}

TEST(ViewerSession, theLogAndStateSayWhatWasServed) {
    ViewerSession session(load_scene(kScenes + "teapot.yaml"), frame_options());
    EXPECT_TRUE(session.state()["last_frame"].is_null());
    ViewRequest request = shaded(ShadingMode::cel);
    request.samples = 4;
    request.msaa = true;
    request.pitch_degrees = 20.0;
    const ViewerFrame frame = session.render(request);
    const nlohmann::json log = session.log();
    ASSERT_EQ(log["frames"].size(), 1u);
    const nlohmann::json& record = log["frames"][0];
    EXPECT_EQ(record["shading"], "cel");
    EXPECT_EQ(record["samples"], 4);
    EXPECT_EQ(record["msaa"], true);
    EXPECT_EQ(record["pitch"], 20.0);
    EXPECT_EQ(record["png_bytes"], frame.png.size());
    EXPECT_EQ(record["png_fnv1a64"], hex64(fnv1a_64(frame.png)));
    EXPECT_GT(record["eye"][1].get<double>(), 3.2);  // raised
    const nlohmann::json state = session.state();
    EXPECT_EQ(state["last_frame"], record);
    EXPECT_EQ(state["scene_settings"]["shading"], "blinn-phong");  // the scene's own, unchanged
    EXPECT_EQ(state["scene_settings"]["filter"], "none");
    EXPECT_NEAR(state["camera"]["elevation_degrees"].get<double>(), 18.07, 0.01);
}

// The check is `raster compare`'s comparison of the request's frame: on the scene as loaded, the same counts and
// the same map as harness::compare_scene gives; on another view, the frame the viewer serves for it.
TEST(ViewerSession, aCheckIsTheComparisonOfTheRequestedFrame) {
    const Scene scene = load_scene(kScenes + "teapot.yaml");
    ViewerSession session(scene, frame_options());
    const ViewerCheck checked = session.check({});
    const harness::Comparison direct = harness::compare_scene(scene, harness::ComparisonOptions{});
    const nlohmann::json& c = checked.result["comparison"];
    EXPECT_EQ(c["genuine_total"], direct.genuine_total());
    EXPECT_EQ(c["ambiguous_total"], direct.visibility.counts.ambiguous_total());
    EXPECT_GT(direct.visibility.counts.ambiguous_total(), 0u);
    EXPECT_EQ(checked.result["verdict"], "pass");
    const std::vector<uint8_t> map = encode_image(harness::diff_map(direct), ImageFormat::png);
    EXPECT_TRUE(checked.map_png == std::string(map.begin(), map.end()));
    EXPECT_EQ(checked.result["map_png_fnv1a64"], hex64(fnv1a_64(checked.map_png)));
    EXPECT_EQ(checked.result["legend"].size(), oracle::diff_map_legend().size());
    // Only the last check's map is kept.
    EXPECT_TRUE(session.check_map(0) == checked.map_png);
    ViewRequest orbited = shaded(ShadingMode::gooch);
    orbited.yaw_degrees = 40.0;
    orbited.samples = 4;
    const ViewerCheck second = session.check(orbited);
    EXPECT_EQ(second.result["index"], 1);
    EXPECT_FALSE(session.check_map(0).has_value());
    EXPECT_EQ(second.result["frame_png_fnv1a64"], hex64(fnv1a_64(session.render(orbited).png)));
    EXPECT_EQ(second.result["comparison"]["samples"], 4);
    EXPECT_EQ(session.log()["checks"].size(), 2u);
    // A frame raster renders but that is past the comparison's memory cap is refused, not attempted.
    ViewRequest sixteen;
    sixteen.samples = 16;
    Scene large = scene;
    large.settings.width = large.settings.height = 2800;
    ASSERT_TRUE(settings_problem(large.settings).empty());
    ViewerSession large_session(large, frame_options());
    try {
        large_session.check(sixteen);
        ADD_FAILURE() << "a 2800 x 2800 frame at 16 samples was compared";
    } catch (const ViewRequestError& error) {
        EXPECT_EQ(std::string(error.what()).rfind("check: comparing a 2800x2800 image with 16 samples", 0), 0u)
            << error.what();
    }
}

TEST(ViewerSession, fnv1aIsTheStandardOne) {
    EXPECT_EQ(fnv1a_64(""), 0xcbf29ce484222325ull);
    EXPECT_EQ(fnv1a_64("a"), 0xaf63dc4c8601ec8cull);
    EXPECT_EQ(hex64(fnv1a_64("foobar")), "85944171f73967e8");
}

}  // namespace
}  // namespace raster::cli
