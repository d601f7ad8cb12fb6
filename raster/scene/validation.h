// Scene validation: what every renderer relies on (image size, frame memory, samples, camera, finite numbers,
// indices in range), checked once whatever format the scene came from, with no I/O.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "raster/scene/scene.h"

namespace raster {

// Bytes the frame buffers of `settings` need (28 per sample: visibility 20, z-buffer 4, winner 4; 4 per pixel of
// image); scenes above kMaxFrameBytes are refused.
inline constexpr uint64_t kMaxFrameBytes = uint64_t{4} << 30;  // 4 GiB
uint64_t frame_bytes(const RenderSettings& settings);
// Bytes the shadow maps of `scene` need: 6 faces of resolution^2 floats per light that casts shadows
// (docs/shadows.md); with frame_bytes, at most kMaxFrameBytes.
uint64_t shadow_map_bytes(const Scene& scene);

// Checks image size and frame memory (shadow maps included), samples and pattern, camera (near > 0, far > near and at most 2^126, fov in
// (0, 180), eye != target, up not parallel to the view direction), snap bits, finite numbers, and triangle indices in
// range.
// Throws InputError naming scene.path.
void validate_scene(const Scene& scene);

// The settings check validate_scene makes, for loaders that point at the offending node: empty when fine, else
// what is wrong.
std::string settings_problem(const RenderSettings& settings);

// The light check (part of validate_scene): empty when fine, else what is wrong.
std::string light_problem(const Light& light);

// The shadow settings check (part of settings_problem): empty when fine, else what is wrong.
std::string shadow_settings_problem(const ShadowSettings& settings);

// The camera check: which value is wrong and what is wrong with it, so a loader can point at that value.
enum class CameraField { eye, target, up, fov, near, far, ortho_height };
struct CameraProblem {
    CameraField field;
    std::string message;  // "camera near must be > 0, got -1.000000"
};
std::optional<CameraProblem> camera_problem(const Camera& camera);

// The model transform check (part of validate_scene): a value not finite, a zero axis or quaternion, a degenerate
// look-at, or a product that may pass kMaxModelMagnitude (model_transform.h); nothing when it can be composed.
std::optional<std::string> model_transform_problem(const ModelTransform& transform);

}  // namespace raster
