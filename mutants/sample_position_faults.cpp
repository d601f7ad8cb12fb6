// The sample positions' faulty variant of the bug catalogue, around the real sample_offsets.
#include "mutants/sample_position_faults.h"

#include <glm/common.hpp>

namespace raster::mutants {

// "wrong sample positions": samples taken half a pixel off (at pixel corners instead of centres, the classic
// missing +0.5), wrapped back into the pixel.
std::vector<glm::vec2> sample_offsets_half_pixel_off(int samples, SamplePattern pattern) {
    std::vector<glm::vec2> offsets = sample_offsets(samples, pattern);
    for (glm::vec2& o : offsets) o = glm::fract(o + 0.5f);
    return offsets;
}

}  // namespace raster::mutants
