// The cases the differential target compares: fuzzer bytes through fuzzed_scene with the target's limits, a
// precision mode, optionally extreme coordinates; kept only when valid and inside what the oracle's precision model
// covers; with the genuine classes the oracle can judge in that mode. Shared by the target and by the excuse
// accounting run over its corpus.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>

#include "harness/comparison/scene_comparison.h"
#include "raster/scene/scene.h"

namespace raster::fuzz {

// Which of the comparison's genuine disagreements the oracle's precision model bounds in the case's modes.
struct JudgedClasses {
    bool visibility = true;     // genuine visibility samples
    bool interpolation = true;  // genuine barycentric and depth samples, and genuine colour pixels
};

struct DifferentialCase {
    Scene scene;
    JudgedClasses judged;
    const char* modes = "default";  // the precision mode drawn, by name
    bool extreme = false;           // extreme coordinates were drawn
};

// The case of `data`, or none when the target skips it.
std::optional<DifferentialCase> differential_case(const uint8_t* data, size_t size);

// The genuine disagreements of the classes judged: what must be 0.
uint64_t judged_genuine(const harness::Comparison& comparison, const JudgedClasses& judged);

}  // namespace raster::fuzz
