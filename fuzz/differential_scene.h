// The cases the differential target compares: fuzzer bytes through fuzzed_scene with the target's limits, a
// precision mode, optionally extreme coordinates; kept only when valid and inside what the oracle's precision model
// covers (what the oracle judges in its mode is the comparison's own rule, harness/comparison/judged_classes.h).
// Shared by the target and by the excuse accounting run over its corpus.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>

#include "harness/comparison/scene_comparison.h"
#include "raster/scene/scene.h"

namespace raster::fuzz {

struct DifferentialCase {
    Scene scene;
    const char* modes = "default";  // the precision mode drawn, by name
    bool extreme = false;           // extreme coordinates were drawn
};

// The case of `data`, or none when the target skips it.
std::optional<DifferentialCase> differential_case(const uint8_t* data, size_t size);

}  // namespace raster::fuzz
