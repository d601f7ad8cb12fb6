// Which samples a correct rasterizer may draw otherwise than the oracle, from the scene alone: per sample, decided
// (class agree: every correct rasterizer shows the oracle's triangle, or nothing, there) or open, with the allowance
// that opens it (an edge band of any triangle near the sample, a clip boundary, an uncertain facing, a depth tie).
// No rasterizer's answer is read, so a grader of images uses it where the comparison has raster's visibility buffer.
// The precision a rasterizer promises (its sub-pixel bits) is the reference geometry's (its radius per triangle).
#pragma once

#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>

#include "oracle/compare/sample_classifier.h"
#include "oracle/reference/reference_geometry.h"
#include "oracle/reference/sample_buffer.h"

namespace raster::oracle {

struct OpennessInputs {
    const SampleBuffer* oracle = nullptr;  // the oracle's visibility at every sample
    const ReferenceGeometry* reference = nullptr;
    std::vector<glm::dvec2> offsets;    // the sample positions inside a pixel
    std::vector<uint8_t> transparent;   // per triangle, 1 for a blended one (the layers' check judges those); may be empty
    int threads = 0;
};

struct SampleOpenness {
    std::vector<SampleClass> classes;  // per sample: agree (decided) or the ambiguous class that opens it
    ComparisonCounts counts;
};

// Every sample's openness. Deterministic for any thread count.
SampleOpenness open_samples(const OpennessInputs& inputs);

}  // namespace raster::oracle
