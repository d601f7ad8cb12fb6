// The layered cases' triangles through the implementation's perspective block.
#include "properties/lens_projection.h"

#include <glm/mat4x4.hpp>

namespace raster::properties {

std::vector<ClipTriangle> project(const Implementation& impl, const LayeredCase& c) {
    const glm::mat4 projection = impl.blocks.perspective(90.0f, static_cast<float>(c.frame.width) / c.frame.height,
                                                         c.frame.volume.near, c.frame.volume.far);
    std::vector<ClipTriangle> out;
    for (const ViewTriangle& t : c.triangles) {
        ClipTriangle clip;
        for (size_t i = 0; i < 3; ++i) clip.v[i] = projection * glm::vec4(t.v[i], 1.0f);
        out.push_back(clip);
    }
    return out;
}

}  // namespace raster::properties
