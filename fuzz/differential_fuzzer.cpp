// Fuzz target: a small random scene rendered by raster's production path and by the independent oracle; the
// comparison must find no genuine disagreement, sample or pixel (genuine_total == 0), or the target traps with the
// comparison and the scene.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>

#include "fuzz/fuzz_check.h"
#include "fuzz/fuzzed_scene.h"
#include "harness/comparison/scene_comparison.h"
#include "raster/core/errors.h"
#include "raster/scene/camera_matrices.h"
#include "raster/scene/validation.h"

namespace {

// Largest projection magnification compared (see the known limitation in LLVMFuzzerTestOneInput).
constexpr double kMaxMagnification = 1e3;

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    FuzzedDataProvider input(data, size);
    raster::fuzz::FuzzedSceneLimits limits;
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
    const raster::Scene scene = raster::fuzz::fuzzed_scene(input, limits);
    try {
        raster::validate_scene(scene);
    } catch (const raster::InputError&) {
        return 0;
    }
    // Known limitation, skipped here: raster works in float clip space, so a projection that magnifies by more
    // than ~1e3 (a field of view under ~0.1 degree) amplifies float rounding past the comparator's bounds: at 1e26
    // the clipped polygon's corners are lost to cancellation (quarter-screen errors), at 6e5 a sliver's
    // barycentrics drift. A non-finite projection is validate_scene's to reject.
    const float focal = raster::projection_matrix(scene.camera, scene.settings.width, scene.settings.height)[1][1];
    if (std::isfinite(focal) && focal > kMaxMagnification) return 0;
    raster::harness::ComparisonOptions options;
    options.threads = 1;  // deterministic and cheap; the result is the same for any count
    const raster::harness::Comparison comparison = raster::harness::compare_scene(scene, options);
    FUZZ_CHECK_EQ(comparison.genuine_total(), uint64_t{0}, [&] {
        return raster::harness::comparison_summary(comparison) + "\n" + raster::harness::genuine_details(comparison) +
               "scene:\n" + raster::fuzz::describe_scene(scene);
    });
    return 0;
}
