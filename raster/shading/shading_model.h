// A shading mode's strategy: how the colour of many visible points is worked out. Each mode is a model of its own
// (flat, Gouraud, Blinn-Phong and Phong, cel, Gooch, unlit), chosen once per frame by the Shader (shade.h).
#pragma once

#include <cstddef>
#include <cstdint>

#include <glm/vec3.hpp>

namespace raster {

class ShadingModel {
public:
    virtual ~ShadingModel() = default;
    // Linear RGB, unclamped, of `count` points, point j on triangle triangle[j] at barycentrics bary[j] (w.r.t. its
    // original vertices), into out[0..count). A point's colour never depends on the other points of the call.
    virtual void shade_many(const uint32_t* triangle, const glm::vec3* bary, size_t count, glm::vec3* out) const = 0;
};

}  // namespace raster
