// The lighting flat and Gouraud shading work out ahead of the samples, once per face or per vertex: with shadow
// maps, each shadowed light's terms kept apart, so that a sample scales them by its own visibility and its shadows
// are as sharp as the per-sample modes'.
#pragma once

#include <cstddef>

#include <glm/vec3.hpp>

#include "raster/scene/scene.h"
#include "raster/shading/lighting.h"
#include "raster/shading/surface.h"

namespace raster {

class PrelitLighting {
public:
    explicit PrelitLighting(const SurfaceLookup& surface);
    // Entries a point's terms take: 1 + the shadowed lights with shadow maps, else 1.
    size_t stride() const { return stride_; }
    // Blinn-Phong terms at a point: stride() entries into `out`, the first for the ambient term and the lights
    // without shadows, then one per shadowed light.
    void light(const glm::vec3& position, const glm::vec3& normal, const Material& material, LightingTerms* out) const;
    // The terms at a sample: each shadowed light's scaled by its visibility (visibility_at's; null: all visible) and
    // added to the first.
    LightingTerms combined(const LightingTerms* terms, const float* visibility) const;

private:
    const SurfaceLookup& surface_;
    size_t stride_ = 1;
};

}  // namespace raster
