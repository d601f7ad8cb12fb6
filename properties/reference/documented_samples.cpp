// The documented sample tables for the properties: the oracle's transcription (oracle/reference/
// sample_positions.h, written from the documents, not from raster's sample code), on the fixed-point grid.
#include "properties/reference/documented_samples.h"

#include <algorithm>
#include <cmath>

#include "oracle/reference/sample_positions.h"

namespace raster::properties {

std::vector<glm::dvec2> documented_sample_offsets(int samples, SamplePattern pattern) {
    return oracle::documented_sample_offsets(samples, pattern);
}

std::vector<reference::Point> documented_fixed_offsets(int samples, SamplePattern pattern, int fixed_bits) {
    const double scale = std::ldexp(1.0, fixed_bits);
    const int64_t last = (int64_t{1} << fixed_bits) - 1;
    std::vector<reference::Point> fixed;
    for (const glm::dvec2& offset : documented_sample_offsets(samples, pattern))
        fixed.push_back({std::min<int64_t>(last, std::llround(offset.x * scale)),
                         std::min<int64_t>(last, std::llround(offset.y * scale))});
    return fixed;
}

}  // namespace raster::properties
