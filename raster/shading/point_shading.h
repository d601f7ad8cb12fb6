// The modes shaded one point at a time: unlit (the base colour), and the stylised cel and Gooch lighting
// (stylized_lighting.h), each lit at the point's own interpolated position and normal.
#pragma once

#include "raster/shading/lighting.h"
#include "raster/shading/shading_model.h"
#include "raster/shading/surface.h"

namespace raster {

// Unlit: the base colour, times the texel when there is one.
class UnlitShading final : public ShadingModel {
public:
    explicit UnlitShading(const SurfaceLookup& surface) : surface_(surface) {}
    void shade_many(const uint32_t* triangle, const glm::vec3* bary, size_t count, glm::vec3* out) const override;

private:
    const SurfaceLookup& surface_;
};

// Cel or Gooch: base * diffuse + specular of the stylised terms, the base colour times the texel when there is one.
class StylizedShading final : public ShadingModel {
public:
    StylizedShading(const SurfaceLookup& surface, ShadingMode mode);  // cel or gooch
    void shade_many(const uint32_t* triangle, const glm::vec3* bary, size_t count, glm::vec3* out) const override;

private:
    LightingTerms light_at(uint32_t triangle, const glm::vec3& bary, const float* visibility) const;

    const SurfaceLookup& surface_;
    bool cel_;  // else Gooch
};

}  // namespace raster
