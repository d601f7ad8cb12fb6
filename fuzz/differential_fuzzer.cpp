// Fuzz target: a small random scene rendered by raster's production path and by the independent oracle; the
// comparison must find no genuine disagreement, sample or pixel (genuine_total == 0), or the target traps with the
// comparison and the scene.
#include <cstddef>
#include <cstdint>
#include <optional>

#include "fuzz/differential_scene.h"
#include "fuzz/fuzz_check.h"
#include "fuzz/fuzzed_scene.h"
#include "harness/comparison/scene_comparison.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::optional<raster::Scene> scene = raster::fuzz::differential_scene(data, size);
    if (!scene) return 0;
    raster::harness::ComparisonOptions options;
    options.threads = 1;  // deterministic and cheap; the result is the same for any count
    const raster::harness::Comparison comparison = raster::harness::compare_scene(*scene, options);
    FUZZ_CHECK_EQ(comparison.genuine_total(), uint64_t{0}, [&] {
        return raster::harness::comparison_summary(comparison) + "\n" + raster::harness::genuine_details(comparison) +
               "scene:\n" + raster::fuzz::describe_scene(*scene);
    });
    return 0;
}
