// The scenes the differential target compares: fuzzer bytes through fuzzed_scene with the target's limits, kept
// only when valid and inside the magnification the oracle's precision model covers. Shared by the target and by
// the excuse accounting run over its corpus.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>

#include "raster/scene/scene.h"

namespace raster::fuzz {

// The scene of `data`, or none when the target skips it.
std::optional<Scene> differential_scene(const uint8_t* data, size_t size);

}  // namespace raster::fuzz
