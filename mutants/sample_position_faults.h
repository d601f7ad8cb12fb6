// The sample positions' faulty variant of the bug catalogue, with the signature of PipelineStages::sample_offsets;
// sample_position_faults.cpp describes the bug where it is written.
#pragma once

#include <vector>

#include <glm/vec2.hpp>

#include "raster/pipeline/sample_pattern.h"

namespace raster::mutants {

// "wrong sample positions"
std::vector<glm::vec2> sample_offsets_half_pixel_off(int samples, SamplePattern pattern);

}  // namespace raster::mutants
