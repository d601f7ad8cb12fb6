// Fuzz target: a small random scene rendered by raster and by the Embree oracle; the comparator must class no
// sample as a genuine disagreement (genuine_total == 0), or the target traps with the comparison and the scene.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>

#include "fuzz/fuzz_check.h"
#include "fuzz/fuzzed_scene.h"
#include "oracle/compare/scene_comparison.h"
#include "raster/core/errors.h"
#include "raster/pipeline/render.h"
#include "raster/pipeline/vertex_stage.h"
#include "raster/scene/validation.h"

namespace {

// Largest projection magnification compared (see the known limitation in LLVMFuzzerTestOneInput).
constexpr double kMaxMagnification = 1e3;

// The first genuine disagreements: where, and what each renderer saw there.
std::string genuine_samples(const raster::oracle::Comparison& comparison) {
    constexpr int kShown = 8;
    std::string text;
    int shown = 0;
    for (size_t i = 0; i < comparison.classes.size() && shown < kShown; ++i) {
        if (!raster::oracle::is_genuine(comparison.classes[i])) continue;
        const auto raster_entry = raster::oracle::sample_entry(comparison.raster.visibility, i);
        const auto oracle_entry = raster::oracle::sample_entry(comparison.oracle_visibility, i);
        const size_t samples = static_cast<size_t>(comparison.samples), width = static_cast<size_t>(comparison.width);
        char line[512];
        const glm::vec3 &a = raster_entry.bary, &b = oracle_entry.bary;
        std::snprintf(line, sizeof line,
                      "  %s at pixel (%zu, %zu) sample %zu:\n    raster triangle %d depth %.9g bary (%.9g, %.9g, %.9g)\n"
                      "    oracle triangle %d depth %.9g bary (%.9g, %.9g, %.9g)\n",
                      raster::oracle::to_string(comparison.classes[i]), (i / samples) % width, i / samples / width,
                      i % samples, int(raster_entry.triangle), double(raster_entry.view_depth), double(a.x), double(a.y),
                      double(a.z), int(oracle_entry.triangle), double(oracle_entry.view_depth), double(b.x), double(b.y),
                      double(b.z));
        text += line;
        ++shown;
    }
    return text;
}

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
    raster::oracle::ComparisonOptions options;
    options.threads = 1;  // deterministic and cheap; the result is the same for any count
    const raster::oracle::Comparison comparison = raster::oracle::compare_scene(scene, options);
    FUZZ_CHECK_EQ(comparison.counts.genuine_total(), uint64_t{0}, [&] {
        return raster::oracle::comparison_summary(comparison) + "\n" + genuine_samples(comparison) + "scene:\n" +
               raster::fuzz::describe_scene(scene);
    });
    return 0;
}
