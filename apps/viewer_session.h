// `raster view`'s frames: the loaded scene kept as it was loaded, each request rendered on a copy of it, one at a
// time, and a record of every frame served (GET /log), so that a test can check what the server really sent.
#pragma once

#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <map>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "apps/viewer_requests.h"
#include "raster/frame/frame.h"
#include "raster/scene/scene.h"

namespace raster::cli {

// What the server knows of one frame it served.
struct ViewerFrameRecord {
    uint64_t index = 0;  // 0 for the session's first frame
    ShadingMode shading = ShadingMode::blinn_phong;
    int samples = 1;
    bool msaa = false;
    std::string filter;  // the filter asked for, or "scene" when the request kept the scene's own
    double yaw_degrees = 0, pitch_degrees = 0, distance = 1;
    std::optional<double> time;  // the instant posed, when the request asked for one
    int camera = 0;              // the file's camera drawn from
    bool shadows = false;        // whether some light cast shadows in the frame
    std::string transparency;    // sorted or weighted (the mode), or opaque
    glm::vec3 eye{0.0f};  // the orbited camera's
    double frame_ms = 0;   // render() alone (RenderStats::ms_total): the X-Frame-Ms header
    double encode_ms = 0;  // the PNG encoding after it
    size_t png_bytes = 0;
    uint64_t png_fnv1a = 0;  // fnv1a_64 of the PNG bytes
};

struct ViewerFrame {
    std::string png;
    ViewerFrameRecord record;
};

// What the check button gets: the oracle's verdict on the frame a request makes (GET /check's body), and the
// disagreement map over it (GET /check-map), as PNG.
struct ViewerCheck {
    nlohmann::json result;  // {index, verdict, frame_png_fnv1a64, map, map_png_fnv1a64, legend, comparison}
    std::string map_png;
};

// Thrown by ViewerSession::render when a request, applied to this scene, is not a valid frame (a 400).
class ViewRequestError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// 64-bit FNV-1a of `bytes` (offset basis 0xcbf29ce484222325, prime 0x100000001b3); the page computes the same.
uint64_t fnv1a_64(std::string_view bytes);
// The hash as the JSON and the page write it: 16 lowercase hex digits.
std::string hex64(uint64_t value);

// A file's cameras, for a scene that places several (glTF): their names, the index of the one the scene was loaded
// with, and how to load the scene drawn from another, as the command loaded the first (its flags applied).
struct ViewerCameras {
    std::vector<std::string> names;
    int loaded = 0;
    std::function<Scene(int camera)> load;
};

class ViewerSession {
public:
    // Keeps `scene` (valid, as load_scene returns it) for the whole session; `options` are every frame's.
    ViewerSession(Scene scene, const RenderOptions& options, ViewerCameras cameras = {});

    // Renders the request on a copy of the scene and records it. One render at a time: concurrent calls wait.
    // Throws ViewRequestError when the request makes an invalid frame (say, 2 samples on a grid pattern).
    ViewerFrame render(const ViewRequest& request);

    // Renders the request's frame through `raster render`'s job and the oracle (harness/comparison), as `raster
    // compare` does, and keeps its map for check_map. Throws ViewRequestError as render does, and when the frame is
    // past the comparison's memory cap.
    ViewerCheck check(const ViewRequest& request);

    // The map of check `index`, if it is the last check's (only that one is kept).
    std::optional<std::string> check_map(uint64_t index) const;

    // GET /state: the scene, its own settings and camera, the request limits, the frames served and the last one.
    nlohmann::json state() const;

    // GET /log: the records of the last kMaxLoggedFrames frames served, oldest first, and of the last checks.
    nlohmann::json log() const;

    static constexpr size_t kMaxLoggedFrames = 1000;

private:
    // The frame a request makes: a copy of the scene with the request applied, checked. Throws ViewRequestError.
    Scene frame_for(const ViewRequest& request);
    // The scene as loaded, or a copy with every textured material's filter set (built once per filter).
    const Scene& scene_with_filter(const std::optional<TextureFilter>& filter);
    // What drawing from another of the file's cameras changes: the camera, the image's size (its aspect) and the
    // animation (which node carries the camera). Loaded once per camera; the rest of that load is dropped.
    struct CameraView {
        Camera camera;
        int width = 0, height = 0;
        std::shared_ptr<const SceneAnimation> animation;
    };
    // `frame` drawn from camera `index`; throws ViewRequestError when the file has no such camera.
    void use_camera(int index, Scene& frame);

    const Scene scene_;
    const ViewerCameras cameras_;
    std::map<int, CameraView> camera_views_;
    std::map<int, std::string> camera_failures_;  // the cameras whose load failed, with the message
    const RenderOptions options_;
    std::map<TextureFilter, Scene> filtered_scenes_;
    RenderResult buffers_;  // reused from frame to frame
    std::deque<ViewerFrameRecord> records_;
    uint64_t frames_served_ = 0;
    std::deque<nlohmann::json> check_records_;  // each check's result without its comparison's detail
    uint64_t checks_done_ = 0;
    std::string last_map_png_;
    mutable std::mutex mutex_;
};

// A record as GET /log and GET /state write it.
nlohmann::json to_json(const ViewerFrameRecord& record);

}  // namespace raster::cli
