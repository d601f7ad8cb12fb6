// The viewer's frames: a request applied to a copy of the kept scene, rendered, encoded, hashed and recorded; and
// its checks: the same frame through raster compare's comparison.
#include "apps/viewer_session.h"

#include <cstdio>
#include <set>

#include "apps/viewer_orbit.h"
#include "harness/comparison/comparison_output.h"
#include "oracle/compare/diff_map.h"
#include "raster/core/stopwatch.h"
#include "raster/image/image.h"
#include "raster/frame/render.h"
#include "raster/scene/validation.h"
#include "raster/texture/mip_chains.h"
#include "raster/transform/scene_pose.h"
#include "raster/scene/animation.h"

namespace raster::cli {
namespace {

nlohmann::json to_json(const glm::vec3& v) { return {v.x, v.y, v.z}; }

// The filter every textured material of the scene uses: its name, "mixed" when they differ, "none" untextured.
std::string scene_filter_name(const Scene& scene) {
    std::set<std::string> filters;
    for (const SceneMesh& mesh : scene.meshes)
        for_each_material(mesh, [&](const Material& material) {
            if (material.texture) filters.insert(to_string(sampler_of(*material.texture, scene.settings.texture_filter).filter));
        });
    if (filters.empty()) return "none";
    return filters.size() == 1 ? *filters.begin() : "mixed";
}

}  // namespace

uint64_t fnv1a_64(std::string_view bytes) {
    uint64_t hash = 0xcbf29ce484222325ull;
    for (const char byte : bytes) {
        hash ^= static_cast<unsigned char>(byte);
        hash *= 0x100000001b3ull;
    }
    return hash;
}

std::string hex64(uint64_t value) {
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(value));
    return text;
}

nlohmann::json to_json(const ViewerFrameRecord& record) {
    return {{"index", record.index},
            {"shading", to_string(record.shading)},
            {"samples", record.samples},
            {"msaa", record.msaa},
            {"filter", record.filter},
            {"yaw", record.yaw_degrees},
            {"pitch", record.pitch_degrees},
            {"distance", record.distance},
            {"time", record.time ? nlohmann::json(*record.time) : nlohmann::json(nullptr)},
            {"camera", record.camera},
            {"shadows", record.shadows},
            {"transparency", record.transparency},
            {"eye", to_json(record.eye)},
            {"frame_ms", record.frame_ms},
            {"encode_ms", record.encode_ms},
            {"png_bytes", record.png_bytes},
            {"png_fnv1a64", hex64(record.png_fnv1a)}};
}

ViewerSession::ViewerSession(Scene scene, const RenderOptions& options, ViewerCameras cameras)
    : scene_(std::move(scene)), cameras_(std::move(cameras)), options_(options) {}

void ViewerSession::use_camera(int index, Scene& frame) {
    if (index == cameras_.loaded) return;
    const int count = static_cast<int>(cameras_.names.size());
    if (index >= count || !cameras_.load)
        throw ViewRequestError("camera " + std::to_string(index) + ": the scene places " + std::to_string(count) +
                               (count == 1 ? " camera" : " cameras"));
    if (const auto failed = camera_failures_.find(index); failed != camera_failures_.end())
        throw ViewRequestError(failed->second);  // not read again for every frame that asks
    auto found = camera_views_.find(index);
    if (found == camera_views_.end()) {
        Scene loaded;
        try {
            loaded = cameras_.load(index);
        } catch (const std::exception& e) {
            throw ViewRequestError(camera_failures_[index] = "camera " + std::to_string(index) + ": " + e.what());
        }
        found = camera_views_.emplace(index, CameraView{loaded.camera, loaded.settings.width, loaded.settings.height,
                                                        loaded.animation}).first;
    }
    frame.camera = found->second.camera;
    frame.settings.width = found->second.width;
    frame.settings.height = found->second.height;
    frame.animation = found->second.animation;
}

const Scene& ViewerSession::scene_with_filter(const std::optional<TextureFilter>& filter) {
    if (!filter) return scene_;
    auto found = filtered_scenes_.find(*filter);
    if (found == filtered_scenes_.end()) {
        Scene filtered = scene_;
        filtered.settings.texture_filter = *filter;
        build_needed_mip_chains(filtered);  // once per filter: the chains are kept with the cached scene
        found = filtered_scenes_.emplace(*filter, std::move(filtered)).first;
    }
    return found->second;
}

Scene ViewerSession::frame_for(const ViewRequest& request) {
    Scene frame = scene_with_filter(request.filter);  // a copy: no request changes what the next one starts from
    RenderSettings& settings = frame.settings;
    if (request.shading) settings.shading = *request.shading;
    if (request.samples) settings.samples = *request.samples;
    if (request.msaa) settings.msaa = *request.msaa;
    if (request.camera) use_camera(*request.camera, frame);
    if (request.shadows) set_shadow_casting(frame, *request.shadows);
    if (request.transparency == TransparencyChoice::opaque) draw_every_material_opaque(frame);
    else if (request.transparency)
        settings.transparency.mode =
            *request.transparency == TransparencyChoice::sorted ? TransparencyMode::sorted : TransparencyMode::weighted;
    if (request.time) {
        if (!frame.animation) throw ViewRequestError("time: the scene has no animation to pose");
        pose_scene(frame, static_cast<float>(*request.time));  // the camera too, where the animation carries it
    }
    frame.camera = orbit_camera(frame.camera, request.yaw_degrees, request.pitch_degrees, request.distance);
    if (std::string problem = settings_problem(settings); !problem.empty()) throw ViewRequestError(problem);
    if (const auto problem = camera_problem(frame.camera)) throw ViewRequestError(problem->message);
    return frame;
}

ViewerFrame ViewerSession::render(const ViewRequest& request) {
    const std::lock_guard<std::mutex> lock(mutex_);
    const Scene frame = frame_for(request);
    const RenderSettings& settings = frame.settings;
    render_into(frame, options_, buffers_);
    const Clock::time_point encode_start = Clock::now();
    const std::vector<uint8_t> png = encode_image(buffers_.image, ImageFormat::png, options_.threads);
    ViewerFrame result{std::string(png.begin(), png.end()), {}};

    ViewerFrameRecord& record = result.record;
    record.encode_ms = milliseconds_since(encode_start);
    record.index = frames_served_++;
    record.shading = settings.shading;
    record.samples = settings.samples;
    record.msaa = settings.msaa;
    record.filter = request.filter ? to_string(*request.filter) : "scene";
    record.yaw_degrees = request.yaw_degrees;
    record.pitch_degrees = request.pitch_degrees;
    record.distance = request.distance;
    record.time = request.time;
    record.camera = request.camera.value_or(cameras_.loaded);
    record.shadows = has_shadows(frame);
    record.transparency = request.transparency == TransparencyChoice::opaque ? "opaque" : to_string(settings.transparency.mode);
    record.eye = frame.camera.eye;
    record.frame_ms = buffers_.stats.ms_total;
    record.png_bytes = result.png.size();
    record.png_fnv1a = fnv1a_64(result.png);
    records_.push_back(record);
    if (records_.size() > kMaxLoggedFrames) records_.pop_front();
    return result;
}

ViewerCheck ViewerSession::check(const ViewRequest& request) {
    const std::lock_guard<std::mutex> lock(mutex_);
    const Scene frame = frame_for(request);
    if (std::string problem = harness::comparison_problem(frame); !problem.empty())
        throw ViewRequestError("check: " + problem);
    harness::ComparisonOptions options;  // raster's job as the viewer renders it
    options.threads = options_.threads;
    options.alpha = options_.alpha;
    options.raster_path = options_.path;
    const harness::Comparison comparison = harness::compare_scene(frame, options);
    // The frame the check judged, encoded as GET /render encodes it: the page holds it to the frame on screen.
    const std::vector<uint8_t> frame_png = encode_image(comparison.raster.image, ImageFormat::png, options_.threads);
    const std::vector<uint8_t> map = encode_image(harness::diff_map(comparison), ImageFormat::png, options_.threads);
    ViewerCheck result{{}, std::string(map.begin(), map.end())};
    const uint64_t index = checks_done_++;
    nlohmann::json legend = nlohmann::json::array();
    for (const oracle::DiffMapKey& key : oracle::diff_map_legend())
        legend.push_back({{"colour", oracle::css_colour(key)}, {"meaning", key.meaning}});
    nlohmann::json record = {{"index", index},
                             {"verdict", comparison.genuine_total() == 0 ? "pass" : "fail"},
                             {"genuine_total", comparison.genuine_total()},
                             {"ambiguous_total", comparison.visibility.counts.ambiguous_total()},
                             {"frame_png_fnv1a64", hex64(fnv1a_64({reinterpret_cast<const char*>(frame_png.data()),
                                                                   frame_png.size()}))},
                             {"map", "/check-map?index=" + std::to_string(index)},
                             {"map_png_fnv1a64", hex64(fnv1a_64(result.map_png))}};
    check_records_.push_back(record);
    if (check_records_.size() > kMaxLoggedFrames) check_records_.pop_front();
    last_map_png_ = result.map_png;
    record["legend"] = std::move(legend);
    record["comparison"] = harness::comparison_json(comparison);
    result.result = std::move(record);
    return result;
}

std::optional<std::string> ViewerSession::check_map(uint64_t index) const {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (checks_done_ == 0 || index != checks_done_ - 1) return std::nullopt;
    return last_map_png_;
}

nlohmann::json ViewerSession::state() const {
    const std::lock_guard<std::mutex> lock(mutex_);
    const Camera& camera = scene_.camera;
    return {{"scene", scene_.path},
            {"width", scene_.settings.width},
            {"height", scene_.settings.height},
            {"textured", has_textures(scene_)},
            {"cameras", {{"names", cameras_.names}, {"loaded", cameras_.loaded}}},
            {"animation", scene_.animation ? nlohmann::json{{"start", scene_.animation->start}, {"end", scene_.animation->end}}
                                           : nlohmann::json(nullptr)},
            {"scene_settings",
             {{"shading", to_string(scene_.settings.shading)},
              {"samples", scene_.settings.samples},
              {"pattern", to_string(scene_.settings.pattern)},
              {"msaa", scene_.settings.msaa},
              {"filter", scene_filter_name(scene_)},
              {"shadows", has_shadows(scene_)},
              {"can_cast_shadows", can_cast_shadows(scene_)},
              {"transparency", to_string(scene_.settings.transparency.mode)},
              {"blended", has_transparency(scene_)}}},
            {"camera",
             {{"eye", to_json(camera.eye)},
              {"target", to_json(camera.target)},
              {"up", to_json(camera.up)},
              {"projection", camera.projection == Projection::orthographic ? "orthographic" : "perspective"},
              {"fov_y_degrees", camera.fov_y_degrees},
              {"ortho_height", camera.ortho_height},
              {"near", camera.near},
              {"far", camera.far},
              {"elevation_degrees", eye_elevation_degrees(camera)}}},
            {"limits",
             {{"yaw_degrees", kMaxYawDegrees},
              {"pitch_degrees", kMaxPitchDegrees},
              {"elevation_degrees", orbit_elevation_limit_degrees(camera)},
              {"distance", {kMinDistance, kMaxDistance}},
              {"samples", {1, kMaxViewSamples}}}},
            {"frames_served", frames_served_},
            {"last_frame", records_.empty() ? nlohmann::json(nullptr) : to_json(records_.back())}};
}

nlohmann::json ViewerSession::log() const {
    const std::lock_guard<std::mutex> lock(mutex_);
    nlohmann::json frames = nlohmann::json::array();
    for (const ViewerFrameRecord& record : records_) frames.push_back(to_json(record));
    nlohmann::json checks = nlohmann::json::array();
    for (const nlohmann::json& record : check_records_) checks.push_back(record);
    return {{"frames_served", frames_served_}, {"frames", frames}, {"checks_done", checks_done_}, {"checks", checks}};
}

}  // namespace raster::cli
