// Flat shading: each face lit once, at its centroid with its geometric normal (Blinn-Phong), one colour per face;
// a texture or a shadow map varies it per sample.
#pragma once

#include <vector>

#include "raster/shading/prelit_lighting.h"
#include "raster/shading/shading_model.h"
#include "raster/shading/surface.h"

namespace raster {

class FlatShading final : public ShadingModel {
public:
    explicit FlatShading(const SurfaceLookup& surface);
    void shade_many(const uint32_t* triangle, const glm::vec3* bary, size_t count, glm::vec3* out) const override;

private:
    // A textured or shadowed point: the face's terms, the texel and the point's light visibility.
    glm::vec3 shade_point(uint32_t triangle, const glm::vec3& bary) const;

    const SurfaceLookup& surface_;
    PrelitLighting lighting_;
    std::vector<glm::vec3> face_color_;      // untextured and unshadowed: per triangle, the final colour
    std::vector<LightingTerms> face_terms_;  // else per triangle, stride() entries of base * diffuse and specular
};

}  // namespace raster
