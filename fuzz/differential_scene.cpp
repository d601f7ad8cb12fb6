// The differential target's scenes: its limits, validation and magnification filter.
#include "fuzz/differential_scene.h"

#include <cmath>

#include <fuzzer/FuzzedDataProvider.h>

#include "fuzz/fuzzed_scene.h"
#include "raster/core/errors.h"
#include "raster/scene/camera_matrices.h"
#include "raster/scene/validation.h"

namespace raster::fuzz {
namespace {

// Largest projection magnification compared (see the known limitation below).
constexpr double kMaxMagnification = 1e3;

}  // namespace

std::optional<Scene> differential_scene(const uint8_t* data, size_t size) {
    FuzzedDataProvider input(data, size);
    FuzzedSceneLimits limits;
    limits.max_side = 32;
    limits.max_grid_side = 2;
    limits.max_triangles = 8;
    // Ordinary positions only: Embree intersects in float, so a triangle with a vertex at 1e9 gets hits that are
    // off by many pixels, which the comparator's bounds (derived from raster's precision) do not cover. Extreme
    // positions are the raster target's business; the lens (fov, near, far) still takes extremes here.
    limits.extreme_coordinates = false;
    // The oracle's precision model is that of the default modes; the cheaper modes disagree by design (measured by
    // `raster tradeoff`, not checked here).
    limits.precision_modes = false;
    Scene scene = fuzzed_scene(input, limits);
    try {
        validate_scene(scene);
    } catch (const InputError&) {
        return std::nullopt;
    }
    // Known limitation, skipped here: raster works in float clip space, so a projection that magnifies by more
    // than ~1e3 (a field of view under ~0.1 degree) amplifies float rounding past the comparator's bounds: at 1e26
    // the clipped polygon's corners are lost to cancellation (quarter-screen errors), at 6e5 a sliver's
    // barycentrics drift. A non-finite projection is validate_scene's to reject.
    const float focal = projection_matrix(scene.camera, scene.settings.width, scene.settings.height)[1][1];
    if (std::isfinite(focal) && focal > kMaxMagnification) return std::nullopt;
    return scene;
}

}  // namespace raster::fuzz
