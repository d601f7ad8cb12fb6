// Blinn-Phong and Phong shading: every point lit at its own interpolated position and normal, in batches of
// kLightingBatch points through the SIMD lighting kernels (lighting_kernels.h), each shadowed light scaled by the
// point's visibility.
#pragma once

#include "raster/shading/lighting_kernels.h"
#include "raster/shading/shading_model.h"
#include "raster/shading/surface.h"

namespace raster {

class BlinnPhongShading final : public ShadingModel {
public:
    // Blinn's half-vector lobe, or Phong's reflection lobe.
    BlinnPhongShading(const SurfaceLookup& surface, SpecularModel specular);
    void shade_many(const uint32_t* triangle, const glm::vec3* bary, size_t count, glm::vec3* out) const override;

private:
    // Up to kLightingBatch points: interpolated into the batch, oriented, shadow visibility per light, lit run by run
    // of one material; the terms are left in `batch`.
    void light_batch(const uint32_t* triangle, const glm::vec3* bary, size_t count, LightingBatch& batch) const;

    const SurfaceLookup& surface_;
    SpecularModel specular_;
};

}  // namespace raster
