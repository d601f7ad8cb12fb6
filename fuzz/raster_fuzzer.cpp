// Fuzz target: the whole rasterizer on a fuzzed camera, settings and triangles, checking the visibility buffer
// against the exact per-sample coverage test, the clipped screen bounds, [near, far], and a fan covered once.
//
// FuzzedDataProvider builds (fuzzed_scene.h): a camera; a resolution up to 128 x 128; samples, pattern, MSAA,
// shading, culling, snap bits and up to two lights; 1 to 64 triangles whose coordinates come from raw float bits, a
// table of extremes or an ordinary range; and here, optionally, a closed fan of 3 to 16 triangles around a shared
// centre placed in front of the camera. Scenes that validate_scene rejects are skipped, as a loader rejects them.
#include <fuzzer/FuzzedDataProvider.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <iomanip>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "fuzz/fuzz_check.h"
#include "fuzz/fuzzed_scene.h"
#include "raster/pipeline/camera_rays.h"
#include "raster/pipeline/clip.h"
#include "raster/core/errors.h"
#include "raster/pipeline/per_sample.h"
#include "raster/pipeline/render.h"
#include "raster/pipeline/sample_pattern.h"
#include "raster/pipeline/setup.h"
#include "raster/pipeline/vertex_stage.h"
#include "raster/scene/validation.h"

// The checks are not what the fuzzer should explore: without coverage instrumentation they cost less and add no
// noise to the coverage signal.
#if defined(__clang__)
#define RASTER_FUZZ_NO_COVERAGE __attribute__((no_sanitize("coverage")))
#else
#define RASTER_FUZZ_NO_COVERAGE
#endif

namespace {

using namespace raster;

constexpr int kMaxFanRim = 16;
// Relative slack on [near, far]: clip-plane intersections and the float 1/w may round a few ulps past a plane.
constexpr double kDepthSlack = 1e-5;
// Slack on original-triangle barycentrics (each in [0, 1], summing to 1) for the float clip interpolation.
constexpr double kBarySlack = 1e-3;
// A fan triangle whose every altitude is at least this many pixels cannot flip when its vertices snap (each moves
// at most 0.35 px even at 1 snap bit), so the fan stays a planar subdivision and exactly-once must hold.
constexpr double kWellConditionedAltitude = 1.0;
// Work limits, so that every input runs in about a millisecond and the fuzzer spends its time on variety: frames
// of at most 2^14 samples (128 x 128 at 1 sample, 64 x 64 at 4, 32 x 32 at 16), and at most 2^16 samples in the
// setups' bounding boxes summed over the triangles. Larger inputs are skipped like invalid ones.
constexpr uint64_t kMaxFrameSamples = uint64_t{1} << 14;
constexpr uint64_t kMaxBoxSamples = uint64_t{1} << 16;
// Most exact per-sample tests spent on the converse coverage check (see check_visibility).
constexpr uint64_t kConverseCheckBudget = uint64_t{1} << 16;

// A closed fan in front of the camera: a centre and 3..16 rim points at increasing angles (each gap under 180
// degrees, so every triangle winds the same way), in a plane tilted away from the image plane by up to 75 degrees.
// Returns false when the floats overflow (a camera far out in float space).
bool fuzzed_fan(FuzzedDataProvider& input, const Camera& camera, const RenderSettings& settings, SceneMesh& fan) {
    const glm::vec3 forward = glm::normalize(camera.target - camera.eye);
    const glm::vec3 side = glm::normalize(glm::cross(forward, camera.up));
    const glm::vec3 up = glm::cross(side, forward);
    const double log_near = std::log(double(camera.near)), log_far = std::log(double(camera.far));
    const double distance = std::exp(log_near + input.ConsumeFloatingPointInRange(0.02, 0.98) * (log_far - log_near));
    const double half_height = distance * std::tan(double(camera.fov_y_degrees) * std::numbers::pi / 360.0);
    const double aspect = double(settings.width) / double(settings.height);
    const double offset_x = input.ConsumeFloatingPointInRange(-0.9, 0.9) * half_height * aspect;
    const double offset_y = input.ConsumeFloatingPointInRange(-0.9, 0.9) * half_height;
    const double radius = input.ConsumeFloatingPointInRange(0.001, 1.0) * half_height;
    const double tilt = input.ConsumeFloatingPointInRange(0.0, 1.3);
    const glm::dvec3 axis_a(side), axis_b = std::cos(tilt) * glm::dvec3(up) + std::sin(tilt) * glm::dvec3(forward);
    const glm::dvec3 centre = glm::dvec3(camera.eye) + distance * glm::dvec3(forward) + offset_x * glm::dvec3(side) +
                              offset_y * glm::dvec3(up);
    const int rim = input.ConsumeIntegralInRange(3, kMaxFanRim);
    const double start = input.ConsumeFloatingPointInRange(0.0, 2.0 * std::numbers::pi);

    fan.source = "fuzzed fan";
    fan.data.positions.push_back(glm::vec3(centre));
    for (int i = 0; i < rim; ++i) {
        const double angle = start + 2.0 * std::numbers::pi * (i + input.ConsumeFloatingPointInRange(0.0, 0.4)) / rim;
        const double length = radius * input.ConsumeFloatingPointInRange(0.3, 1.0);
        fan.data.positions.push_back(
            glm::vec3(centre + length * (std::cos(angle) * axis_a + std::sin(angle) * axis_b)));
        fan.data.triangles.push_back({{0, uint32_t(1 + i), uint32_t(1 + (i + 1) % rim)}});
    }
    return std::all_of(fan.data.positions.begin(), fan.data.positions.end(),
                       [](const glm::vec3& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); });
}

// A scene triangle as the checks see it: its clipped polygon, the setups made from it, its screen bounds.
struct CheckedTriangle {
    ClippedPolygon polygon;
    size_t first_setup = 0, end_setup = 0;
    double min_x = 0, min_y = 0, max_x = 0, max_y = 0;  // of the clipped polygon, in pixels
    double min_altitude = 0;                            // of the unclipped triangle, in pixels
};

glm::dvec2 to_screen(const glm::vec4& clip, const RenderSettings& settings) {
    const double inv_w = 1.0 / double(clip.w);
    return screen_from_ndc(double(clip.x) * inv_w, double(clip.y) * inv_w, settings.width, settings.height);
}

double min_altitude(const glm::dvec2 (&p)[3]) {
    const double area2 = std::fabs((p[1].x - p[0].x) * (p[2].y - p[0].y) - (p[1].y - p[0].y) * (p[2].x - p[0].x));
    double altitude = std::numeric_limits<double>::infinity();
    for (int i = 0; i < 3; ++i) altitude = std::min(altitude, area2 / glm::length(p[(i + 2) % 3] - p[(i + 1) % 3]));
    return altitude;
}

std::string where(int x, int y, int s, uint32_t triangle) {
    return "pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") sample " + std::to_string(s) +
           " triangle " + std::to_string(triangle);
}

std::string describe(const glm::vec4& v) {
    std::ostringstream text;
    text << std::setprecision(9) << "(" << v.x << ", " << v.y << ", " << v.z << ", " << v.w << ")";
    return text.str();
}

// Calls visit(index, X, Y) for every sample in the setup's pixel bounding box (X, Y in fixed point).
template <class Visit>
RASTER_FUZZ_NO_COVERAGE void for_each_sample_in_box(const TriangleSetup& setup, const VisibilityBuffer& buffer,
                                                    const FixedSampleOffsets& offsets, int fixed_bits, Visit&& visit) {
    for (int py = setup.min_y; py <= setup.max_y; ++py)
        for (int px = setup.min_x; px <= setup.max_x; ++px)
            for (int s = 0; s < buffer.samples; ++s)
                visit(buffer.index(px, py, s), (int64_t{px} << fixed_bits) + offsets.x[s],
                      (int64_t{py} << fixed_bits) + offsets.y[s]);
}

uint64_t box_samples(const TriangleSetup& setup, int samples) {
    return uint64_t(setup.max_x - setup.min_x + 1) * uint64_t(setup.max_y - setup.min_y + 1) * uint64_t(samples);
}

class Checker {
public:
    explicit Checker(const Scene& scene)
        : scene_(scene), settings_(scene.settings),
          fixed_bits_(fixed_bits_for(settings_.snap_bits)),
          offsets_(fixed_sample_offsets(sample_offsets(settings_.samples, settings_.pattern), fixed_bits_)) {
        // The same stages render() ran, recomputed here to know each triangle's polygon and setups.
        const TransformedScene geometry = run_vertex_stage(scene, vertex_stage_needs(settings_.shading));
        const FrameParams params = frame_params_for(scene, sample_offsets(settings_.samples, settings_.pattern), 1);
        const ClipVolume& volume = params.clip;
        triangles_.resize(geometry.triangles.size());
        for (size_t t = 0; t < geometry.triangles.size(); ++t) {
            CheckedTriangle& checked = triangles_[t];
            const TriangleIndices& v = geometry.triangles[t];
            checked.polygon = clip_triangle(geometry.clip[v.v[0]], geometry.clip[v.v[1]], geometry.clip[v.v[2]], volume);
            checked.first_setup = setups_.size();
            const bool culled = settings_.cull_backfaces &&
                                !faces_front(geometry.clip[v.v[0]], geometry.clip[v.v[1]], geometry.clip[v.v[2]]);
            if (!culled) setup_polygon(checked.polygon, static_cast<uint32_t>(t), params, setups_);
            checked.end_setup = setups_.size();
            if (checked.polygon.count == 0) continue;
            checked.min_x = checked.min_y = std::numeric_limits<double>::infinity();
            checked.max_x = checked.max_y = -std::numeric_limits<double>::infinity();
            for (int i = 0; i < checked.polygon.count; ++i) {
                const glm::dvec2 p = to_screen(checked.polygon.vertices[i].position, settings_);
                checked.min_x = std::min(checked.min_x, p.x), checked.max_x = std::max(checked.max_x, p.x);
                checked.min_y = std::min(checked.min_y, p.y), checked.max_y = std::max(checked.max_y, p.y);
            }
            if (!checked.polygon.clipped) {
                const glm::dvec2 corners[3] = {to_screen(geometry.clip[v.v[0]], settings_),
                                               to_screen(geometry.clip[v.v[1]], settings_),
                                               to_screen(geometry.clip[v.v[2]], settings_)};
                checked.min_altitude = min_altitude(corners);
            }
        }
    }

    // Samples in the setups' bounding boxes, summed: the rasterizer's work for this scene, near enough.
    uint64_t box_sample_total() const {
        uint64_t total = 0;
        for (const TriangleSetup& setup : setups_) total += box_samples(setup, settings_.samples);
        return total;
    }

    // Every sample the exact test covers is covered in the buffer and vice versa; each covered sample is covered
    // by a setup of its own triangle, lies inside that triangle's clipped screen bounds (plus the snap error), and
    // has a depth in [near, far] and barycentrics in [0, 1] summing to 1.
    RASTER_FUZZ_NO_COVERAGE void check_visibility(const VisibilityBuffer& buffer) const {
        // The converse (every sample some setup covers is covered in the buffer) costs one exact test per sample
        // of every setup's box: it is checked when that stays within budget.
        const bool check_converse = box_sample_total() <= kConverseCheckBudget;
        std::vector<uint8_t> covered_by_any(check_converse ? buffer.size() : 0, 0);
        for (size_t k = 0; check_converse && k < setups_.size(); ++k)
            for_each_sample_in_box(setups_[k], buffer, offsets_, fixed_bits_, [&](size_t index, int64_t X, int64_t Y)
                                       RASTER_FUZZ_NO_COVERAGE { covered_by_any[index] |= covers(setups_[k], X, Y); });
        const double snap_slack = 0.5 / double(int64_t{1} << settings_.snap_bits) + 1e-9;
        const double sample_scale = 1.0 / double(int64_t{1} << fixed_bits_);
        for (int py = 0; py < buffer.height; ++py)
            for (int px = 0; px < buffer.width; ++px)
                for (int s = 0; s < buffer.samples; ++s) {
                    const size_t index = buffer.index(px, py, s);
                    const uint32_t id = buffer.triangle[index];
                    const auto context = [&] { return where(px, py, s, id) + "\n" + describe_triangle(id); };
                    if (check_converse) FUZZ_CHECK_EQ(int{id != kNoTriangle}, int{covered_by_any[index]}, context);
                    if (id == kNoTriangle) continue;
                    const int64_t X = (int64_t{px} << fixed_bits_) + offsets_.x[s];
                    const int64_t Y = (int64_t{py} << fixed_bits_) + offsets_.y[s];
                    const CheckedTriangle& triangle = triangles_.at(id);
                    bool covered_by_own = false;
                    for (size_t k = triangle.first_setup; k < triangle.end_setup; ++k)
                        covered_by_own = covered_by_own || covers(setups_[k], X, Y);
                    FUZZ_CHECK_EQ(covered_by_own, true, context);

                    const double x = double(X) * sample_scale, y = double(Y) * sample_scale;
                    FUZZ_CHECK_GE(x, triangle.min_x - snap_slack, context);
                    FUZZ_CHECK_LE(x, triangle.max_x + snap_slack, context);
                    FUZZ_CHECK_GE(y, triangle.min_y - snap_slack, context);
                    FUZZ_CHECK_LE(y, triangle.max_y + snap_slack, context);

                    const double depth = buffer.view_depth[index];
                    FUZZ_CHECK_GE(depth, double(scene_.camera.near) * (1.0 - kDepthSlack), context);
                    FUZZ_CHECK_LE(depth, double(scene_.camera.far) * (1.0 + kDepthSlack), context);

                    const glm::dvec3 bary(buffer.bary[index]);
                    for (int i = 0; i < 3; ++i) {
                        FUZZ_CHECK_GE(bary[i], -kBarySlack, context);
                        FUZZ_CHECK_LE(bary[i], 1.0 + kBarySlack, context);
                    }
                    FUZZ_CHECK_LE(std::fabs(bary.x + bary.y + bary.z - 1.0), kBarySlack, context);
                }
    }

    // Triangles [first, end) form a closed fan around their shared first vertex. It is checkable when every one of
    // them is entirely inside the view volume, well conditioned and kept by setup as one triangle. (Instrumented,
    // unlike the checks, so that the fuzzer is rewarded for reaching a checkable fan.)
    bool fan_is_checkable(size_t first, size_t end) const {
        for (size_t t = first; t < end; ++t) {
            const CheckedTriangle& triangle = triangles_[t];
            if (triangle.polygon.clipped || triangle.polygon.count != 3 || triangle.end_setup != triangle.first_setup + 1 ||
                !(triangle.min_altitude >= kWellConditionedAltitude))
                return false;
        }
        return true;
    }

    // For a checkable fan, every sample of the fan's interior (inside a fan triangle, off the rim) is covered
    // exactly once, and no sample twice.
    RASTER_FUZZ_NO_COVERAGE void check_fan(const VisibilityBuffer& buffer, size_t first, size_t end) const {
        std::vector<uint8_t> count(buffer.size(), 0), interior(buffer.size(), 0);
        for (size_t t = first; t < end; ++t) {
            const TriangleSetup& setup = setups_[triangles_[t].first_setup];
            // Setup vertex 0 is the polygon's first vertex, the fan's centre, so edge 0 is the rim edge.
            for_each_sample_in_box(setup, buffer, offsets_, fixed_bits_, [&](size_t index, int64_t X, int64_t Y)
                                       RASTER_FUZZ_NO_COVERAGE {
                count[index] += covers(setup, X, Y);
                int64_t edge[3];
                for (int i = 0; i < 3; ++i) edge[i] = setup.a[i] * X + setup.b[i] * Y + setup.c[i];
                interior[index] |= edge[0] > 0 && edge[1] >= 0 && edge[2] >= 0;
            });
        }
        for (int py = 0; py < buffer.height; ++py)
            for (int px = 0; px < buffer.width; ++px)
                for (int s = 0; s < buffer.samples; ++s) {
                    const size_t index = buffer.index(px, py, s);
                    const auto context = [&] { return where(px, py, s, buffer.triangle[index]) + " (fan)"; };
                    FUZZ_CHECK_LE(int{count[index]}, 1, context);
                    if (interior[index]) FUZZ_CHECK_EQ(int{count[index]}, 1, context);
                }
    }

private:
    // The triangle's clipped polygon (clip space and pixels) and its setups' snapped vertices, for failure reports.
    std::string describe_triangle(uint32_t id) const {
        if (id >= triangles_.size()) return "no such triangle";
        const CheckedTriangle& triangle = triangles_[id];
        std::ostringstream text;
        text << std::setprecision(9) << "  clipped polygon (" << triangle.polygon.count << " vertices):\n";
        for (int i = 0; i < triangle.polygon.count; ++i) {
            const glm::dvec2 p = to_screen(triangle.polygon.vertices[i].position, settings_);
            text << "    clip " << describe(triangle.polygon.vertices[i].position) << " -> pixels (" << p.x << ", " << p.y
                 << ")\n";
        }
        for (size_t k = triangle.first_setup; k < triangle.end_setup; ++k) {
            const TriangleSetup& setup = setups_[k];
            text << "  setup " << k << ": fixed-point vertices";
            for (int i = 0; i < 3; ++i) text << " (" << setup.x[i] << ", " << setup.y[i] << ")";
            text << " in units of 1/" << (int64_t{1} << fixed_bits_) << " px, area2 " << setup.area2 << "\n";
        }
        return text.str();
    }

    const Scene& scene_;
    const RenderSettings& settings_;
    int fixed_bits_;
    FixedSampleOffsets offsets_;
    std::vector<CheckedTriangle> triangles_;
    std::vector<TriangleSetup> setups_;
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    FuzzedDataProvider input(data, size);
    // 1-64 triangles, 1-128 pixels a side, standard patterns and grids up to 4 x 4 (16 samples at most).
    Scene scene = raster::fuzz::fuzzed_scene(input, raster::fuzz::FuzzedSceneLimits{});
    const size_t fan_first = triangle_count(scene);
    const bool with_fan = input.ConsumeBool();
    RenderOptions options;
    options.threads = 1;  // deterministic and cheap; the output is the same for any count
    options.alpha = input.ConsumeBool();
    const uint64_t frame_samples =
        uint64_t(scene.settings.width) * uint64_t(scene.settings.height) * uint64_t(scene.settings.samples);
    if (camera_problem(scene.camera) || frame_samples > kMaxFrameSamples) return 0;
    SceneMesh fan;
    if (with_fan && fuzzed_fan(input, scene.camera, scene.settings, fan)) scene.meshes.push_back(std::move(fan));
    try {
        validate_scene(scene);
    } catch (const InputError&) {
        return 0;
    }

    const Checker checker(scene);
    if (checker.box_sample_total() > kMaxBoxSamples) return 0;
    const RenderResult result = render(scene, options);
    checker.check_visibility(result.visibility);
    if (scene.meshes.size() == 2 && checker.fan_is_checkable(fan_first, triangle_count(scene)))
        checker.check_fan(result.visibility, fan_first, triangle_count(scene));
    return 0;
}
