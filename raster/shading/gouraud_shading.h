// Gouraud shading: each vertex lit once (Blinn-Phong, at its normal), the colours interpolated over the triangle; a
// texture multiplies the interpolated base * diffuse, and a shadow map scales each light's vertex terms per sample.
#pragma once

#include <vector>

#include "raster/shading/prelit_lighting.h"
#include "raster/shading/shading_model.h"
#include "raster/shading/surface.h"

namespace raster {

class GouraudShading final : public ShadingModel {
public:
    explicit GouraudShading(const SurfaceLookup& surface);
    void shade_many(const uint32_t* triangle, const glm::vec3* bary, size_t count, glm::vec3* out) const override;

private:
    const LightingTerms* corner_terms(uint32_t triangle, int corner) const;
    // A textured or shadowed point: the corners' terms (scaled by the point's light visibility) interpolated.
    glm::vec3 shade_point(uint32_t triangle, const glm::vec3& bary) const;

    const SurfaceLookup& surface_;
    PrelitLighting lighting_;
    bool per_corner_ = false;                  // a mesh has several materials: terms per triangle corner
    std::vector<LightingTerms> vertex_terms_;  // per global vertex, or per triangle corner (3 t + k) when
                                               // per_corner_; stride() entries each
    std::vector<glm::vec3> corner_color_;      // without textures or shadows: per triangle corner (3 t + k), the
                                               // final colour base * diffuse + specular, which shade_many interpolates
};

}  // namespace raster
