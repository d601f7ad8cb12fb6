// The oracle's comparisons as checks for the mutants run: one per corpus scene, each catching a bug when the
// faulty pipeline disagrees with the Embree oracle genuinely more often than the real pipeline does.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "properties/implementation.h"

namespace raster::properties {

// The checks' names, "Oracle.<scene>": every scene of corpus/scenes at one sample per pixel, near_crossing with its
// near plane moved to 2 (so that geometry behind the eye would show), and a lit triangle under an attenuating light
// (the corpus has none). Touches no Embree state, so the caller may fork afterwards.
std::vector<std::string> oracle_checks();

// "" when the implementation has at most as many genuine disagreements with the oracle on the check's scene as the
// real pipeline (measured here, once per process), else how many and of which kinds.
std::string run_oracle_check(const std::string& check, const Implementation& impl);

}  // namespace raster::properties
