// Fuzz target: a small random scene, in a precision mode the oracle can bound and sometimes with extreme
// coordinates (differential_scene.h), rendered by raster's production path and by the independent oracle; the
// comparison must find no genuine disagreement, sample or pixel, of the classes the oracle judges in that mode, or
// the target traps with the comparison and the scene.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

#include "fuzz/differential_scene.h"
#include "fuzz/fuzz_check.h"
#include "fuzz/fuzzed_scene.h"
#include "harness/comparison/comparison_output.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::optional<raster::fuzz::DifferentialCase> input = raster::fuzz::differential_case(data, size);
    if (!input) return 0;
    raster::harness::ComparisonOptions options;
    options.threads = 1;  // deterministic and cheap; the result is the same for any count
    const raster::harness::Comparison comparison = raster::harness::compare_scene(input->scene, options);
    FUZZ_CHECK_EQ(comparison.genuine_total(), uint64_t{0}, [&] {
        return std::string("modes: ") + input->modes + "\n" + raster::harness::comparison_summary(comparison) + "\n" +
               raster::harness::genuine_details(comparison) +
               "scene:\n" + raster::fuzz::describe_scene(input->scene);
    });
    return 0;
}
