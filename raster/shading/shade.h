// Shading: the colour of a visible point from its triangle id and barycentrics, by the shading model of the scene's
// mode (shading_model.h), with the scene's textures and shadow maps.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>

#include <glm/vec3.hpp>

#include "raster/geometry/vertex_stage.h"
#include "raster/scene/scene.h"
#include "raster/shading/shading_model.h"
#include "raster/shading/surface.h"

namespace raster {

class ShadowMaps;  // shadow_maps.h

// Everything shading needs, prepared once per frame for the scene's shading mode: the surface lookup every mode
// reads, and the mode's model (per-face colours for flat, per-vertex terms for Gouraud, nothing extra for the
// per-point modes). Holds pointers into `scene`, `geometry` and `shadows`, which must outlive it.
//
// With shadow maps, each light that casts shadows is scaled by its visibility at the point being shaded: Phong,
// Blinn-Phong, cel and Gooch pass it to their lighting; flat and Gouraud keep that light's terms apart (per face,
// per vertex) and scale them per sample, so their shadows are as sharp as the other modes'.
class Shader {
public:
    Shader(const Scene& scene, const TransformedScene& geometry, const ShadowMaps* shadows = nullptr);
    Shader(const Shader&) = delete;  // the model refers to the surface lookup
    Shader& operator=(const Shader&) = delete;

    // Linear RGB of triangle `triangle` at barycentrics `bary` (w.r.t. its original vertices), unclamped.
    glm::vec3 shade(uint32_t triangle, const glm::vec3& bary) const;
    // shade() of `count` points into out[0..count): the same bits, many points per call (Blinn-Phong and Phong are
    // lit in SIMD batches).
    void shade_many(const uint32_t* triangle, const glm::vec3* bary, size_t count, glm::vec3* out) const {
        model_->shade_many(triangle, bary, count, out);
    }
    // The opacity of triangle `triangle` at barycentrics `bary` (1 opaque): its material's, times its texture's
    // alpha where the texture reads alpha, cut to 0 or 1 for a cut-out (SurfaceLookup::opacity).
    float opacity(uint32_t triangle, const glm::vec3& bary) const { return surface_.opacity(triangle, bary); }

private:
    SurfaceLookup surface_;
    std::unique_ptr<ShadingModel> model_;
};

}  // namespace raster
