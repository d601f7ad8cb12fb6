// Fuzz target: the production renderer (render(), tiled, as users run it) on a fuzzed camera, settings, precision
// modes and triangles, its visibility buffer checked sample by sample against the independent exact reference
// (reference_frame.h: the reference's own facing and view-volume tests, snapping, top-left rule and depth rule),
// with the invariants of visibility_invariants.h, each stating the modes it holds for.
//
// FuzzedDataProvider builds (fuzzed_scene.h): a camera; a resolution up to 128 x 128; samples, pattern, MSAA,
// shading, culling, snap bits, the precision modes and up to two lights; 1 to 64 triangles whose coordinates come
// from raw float bits, a table of extremes or an ordinary range; and here, optionally, a closed fan of 3 to 16
// triangles around a shared centre placed in front of the camera, then up to 3 exact copies of earlier triangles
// (ties that the depth rule must give to the earlier one). Scenes that validate_scene rejects are skipped, as a
// loader rejects them.
#include <fuzzer/FuzzedDataProvider.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>

#include "fuzz/fuzzed_scene.h"
#include "fuzz/reference_frame.h"
#include "fuzz/visibility_invariants.h"
#include "raster/core/errors.h"
#include "raster/frame/render.h"
#include "raster/geometry/vertex_stage.h"
#include "raster/scene/validation.h"

namespace {

using namespace raster;

constexpr int kMaxFanRim = 16;
// Exact copies of earlier triangles per input: the only ties whose keys are known to be equal.
constexpr int kMaxCopies = 3;
// A fan triangle whose every altitude is at least this many pixels cannot flip when its vertices snap (each moves
// at most 0.35 px even at 1 snap bit), so the fan stays a planar subdivision and exactly-once must hold.
constexpr double kWellConditionedAltitude = 1.0;
// Work limits, so that inputs run in well under a millisecond under the sanitizers and the fuzzer spends its time on
// variety: frames of at most 3 x 2^12 samples (128 x 96 at 1 sample, 64 x 48 at 4, 32 x 24 at 16; sides stay up to
// 128, so frames still span 2 x 2 tiles), and at most 2^15 samples in the reference pieces' boxes summed over the
// triangles. Larger inputs are skipped like invalid ones. (At 2^14 and 2^16 the target ran about 1,200 inputs a
// second; these limits keep it over 1,500.)
constexpr uint64_t kMaxFrameSamples = uint64_t{3} << 12;
constexpr uint64_t kMaxBoxSamples = uint64_t{1} << 15;

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
    mutable_data(fan).positions.push_back(glm::vec3(centre));
    for (int i = 0; i < rim; ++i) {
        const double angle = start + 2.0 * std::numbers::pi * (i + input.ConsumeFloatingPointInRange(0.0, 0.4)) / rim;
        const double length = radius * input.ConsumeFloatingPointInRange(0.3, 1.0);
        mutable_data(fan).positions.push_back(
            glm::vec3(centre + length * (std::cos(angle) * axis_a + std::sin(angle) * axis_b)));
        mutable_data(fan).triangles.push_back({{0, uint32_t(1 + i), uint32_t(1 + (i + 1) % rim)}});
    }
    return std::all_of(fan.data->positions.begin(), fan.data->positions.end(),
                       [](const glm::vec3& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); });
}

// Up to kMaxCopies exact copies of earlier triangles (of any mesh), as a mesh of their own.
SceneMesh fuzzed_copies(FuzzedDataProvider& input, const Scene& scene) {
    SceneMesh copies;
    copies.source = "fuzzed copies";
    std::vector<const glm::vec3*> corners;
    for (const SceneMesh& mesh : scene.meshes)
        for (const TriangleIndices& t : mesh.data->triangles)
            for (uint32_t v : t.v) corners.push_back(&mesh.data->positions[v]);
    const int count = corners.empty() ? 0 : input.ConsumeIntegralInRange(0, kMaxCopies);
    for (int c = 0; c < count; ++c) {
        const size_t first = 3 * input.ConsumeIntegralInRange<size_t>(0, corners.size() / 3 - 1);
        const auto at = static_cast<uint32_t>(copies.data->positions.size());
        for (size_t k = 0; k < 3; ++k) mutable_data(copies).positions.push_back(*corners[first + k]);
        mutable_data(copies).triangles.push_back({{at, at + 1, at + 2}});
    }
    return copies;
}

// The angle at the fan's centre (vertex 0) of a piece, in (0, pi).
double centre_angle(const fuzz::ReferencePiece& piece) {
    const double ax = double(piece.vertex[1].at.x - piece.vertex[0].at.x);
    const double ay = double(piece.vertex[1].at.y - piece.vertex[0].at.y);
    const double bx = double(piece.vertex[2].at.x - piece.vertex[0].at.x);
    const double by = double(piece.vertex[2].at.y - piece.vertex[0].at.y);
    return std::atan2(std::fabs(ax * by - ay * bx), ax * bx + ay * by);
}

// Triangles [first, end) form a closed fan around their shared first vertex. It is checkable (check_fan) with
// fixed-point edges when every one of them is drawn unclipped as one piece of certain facing, well conditioned, and
// the snapped fan still goes once around its centre: every piece wound the same way and their angles there summing
// to one turn. (Float vertex positions can fold a fan placed a few ulps from the eye whatever its altitudes: the
// fuzzer found a 3-triangle fan whose third triangle was wound the other way, covering its neighbours.)
// Instrumented, unlike the checks, so that the fuzzer is rewarded for reaching a checkable fan.
bool fan_is_checkable(const fuzz::ReferenceFrame& reference, size_t first, size_t end) {
    if (reference.float_edges()) return false;
    double turn = 0.0;
    for (size_t t = first; t < end; ++t) {
        const fuzz::ReferenceTriangle& triangle = reference.triangles()[t];
        if (!triangle.inside_volume || triangle.end_piece != triangle.first_piece + 1 ||
            !(triangle.min_altitude >= kWellConditionedAltitude))
            return false;
        const fuzz::ReferencePiece& piece = reference.pieces()[triangle.first_piece];
        if (!piece.certain || piece.reversed != reference.pieces()[reference.triangles()[first].first_piece].reversed)
            return false;
        turn += centre_angle(piece);
    }
    // A consistently wound closed fan turns a whole number of times: 2 pi, or 4 pi and more when it folds.
    return turn < 3.0 * std::numbers::pi;
}

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
    const bool fan_made = with_fan && fuzzed_fan(input, scene.camera, scene.settings, fan);
    if (fan_made) scene.meshes.push_back(std::move(fan));
    const size_t fan_end = triangle_count(scene);
    SceneMesh copies = fuzzed_copies(input, scene);
    if (!copies.data->triangles.empty()) scene.meshes.push_back(std::move(copies));
    try {
        validate_scene(scene);
    } catch (const InputError&) {
        return 0;
    }

    const TransformedScene geometry = run_vertex_stage(scene, vertex_stage_needs(scene.settings.shading));
    const raster::fuzz::ReferenceFrame reference(scene, geometry);
    if (reference.box_samples() > kMaxBoxSamples) return 0;
    // The buffers are reused from input to input, as a real-time renderer reuses its framebuffers (render_into):
    // fresh full-frame planes would cost page faults on every input.
    static RenderResult result;
    render_into(scene, options, result);
    raster::fuzz::check_visibility(reference, result.visibility, scene);
    if (fan_made && fan_is_checkable(reference, fan_first, fan_end))
        raster::fuzz::check_fan(reference, result.visibility, static_cast<uint32_t>(fan_first),
                                static_cast<uint32_t>(fan_end), scene);
    return 0;
}
