// Shading: the colour of a visible point from its triangle id and barycentrics, with the lighting model of the
// scene's shading mode, its textures and its shadow maps.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "raster/shading/lighting.h"
#include "raster/shading/texture_lookup.h"
#include "raster/geometry/vertex_stage.h"
#include "raster/scene/scene.h"

namespace raster {

class ShadowMaps;  // shadow_maps.h

// Everything shading needs, prepared once per frame for the scene's shading mode: per-vertex lit terms for
// Gouraud, per-face colours for flat, texture coordinates and gradients for textured triangles, face normals for
// the shadow maps' bias, nothing extra for unlit. Holds pointers into `scene`, `geometry` and `shadows`, which must
// outlive it.
//
// With shadow maps, each light that casts shadows is scaled by its visibility at the point being shaded: Phong,
// Blinn-Phong, cel and Gooch pass it to their lighting; flat and Gouraud keep that light's terms apart (per face,
// per vertex) and scale them per sample, so their shadows are as sharp as the other modes'.
class Shader {
public:
    Shader(const Scene& scene, const TransformedScene& geometry, const ShadowMaps* shadows = nullptr);

    // Linear RGB of triangle `triangle` at barycentrics `bary` (w.r.t. its original vertices), unclamped.
    glm::vec3 shade(uint32_t triangle, const glm::vec3& bary) const;
    // shade() of `count` points into out[0..count): the same bits, with Blinn-Phong and Phong lit in SIMD batches.
    void shade_many(const uint32_t* triangle, const glm::vec3* bary, size_t count, glm::vec3* out) const;
    // The opacity of the triangle's material (1 opaque).
    float opacity(uint32_t triangle) const { return material(triangle).opacity; }

private:
    // The face colour, else the interpolated vertex colour, else the material colour; no texture.
    glm::vec3 base_color(uint32_t triangle, const glm::vec3& bary) const;
    // Whether base_color varies over the triangle (interpolated vertex colours), else it is one colour.
    bool base_varies(uint32_t triangle) const;
    // The texture's value at the point when the triangle's material has one (it multiplies the base colour).
    bool texture_factor(uint32_t triangle, const glm::vec3& bary, glm::vec3& factor) const;
    const Material& material(uint32_t triangle) const;
    // One point, every mode but Blinn-Phong and Phong, which shade_many lights in batches.
    glm::vec3 shade_point(uint32_t triangle, const glm::vec3& bary) const;
    // A lit colour: base * diffuse + specular.
    static glm::vec3 lit(const glm::vec3& base, const LightingTerms& terms) {
        return base * terms.diffuse + terms.specular;
    }
    // base * diffuse + specular, the base colour times the texel when there is one (Phong, Blinn-Phong, cel, Gooch).
    glm::vec3 lit_color(uint32_t triangle, const glm::vec3& bary, const glm::vec3* texel,
                        const LightingTerms& terms) const;
    // A triangle's world positions and normals at its three corners.
    struct SurfaceCorners {
        glm::vec3 position[3], normal[3];
    };
    SurfaceCorners surface_corners(uint32_t triangle) const;
    // The world position and the interpolated (not yet unit) normal at the point.
    static void surface_at(const SurfaceCorners& corners, const glm::vec3& bary, glm::vec3& position,
                           glm::vec3& normal);
    LightingTerms light_at(uint32_t triangle, const glm::vec3& bary, const float* visibility) const;
    // Up to kLightingBatch Blinn-Phong or Phong points: interpolated into the batch, oriented, shadow visibility per
    // light, lit run by run of one material; the terms are left in `batch`.
    void light_batch(const uint32_t* triangle, const glm::vec3* bary, size_t count, LightingBatch& batch) const;
    // Flat and Gouraud's terms at a face or corner: terms_stride_ entries, each shadowed light's scaled by its
    // visibility and added to the first (ambient and the lights without shadows).
    LightingTerms combined(const LightingTerms* terms, const float* visibility) const;
    const LightingTerms* corner_terms(uint32_t triangle, int corner) const;
    // Every scene light's visibility at the point (1 for a light without shadows), in a per-thread buffer; null
    // without shadow maps.
    const float* visibility_at(uint32_t triangle, const glm::vec3& bary) const;
    // Each shadowed light's visibility at `position` on `triangle`, into out[light * stride]; the other lights'
    // entries are left as they are.
    void shadow_visibility(uint32_t triangle, const glm::vec3& position, float* out, size_t stride) const;
    // Lit terms for flat and Gouraud at a point: terms_stride_ entries into `out`.
    void lit_terms(const glm::vec3& position, const glm::vec3& normal, const Material& material,
                   LightingTerms* out) const;

    const Scene& scene_;
    const TransformedScene& geometry_;
    ShadingMode mode_;
    SpecularModel specular_model_;             // Phong's lobe for phong, Blinn's for the other lit modes
    bool lights_in_batches_ = false;           // Blinn-Phong or Phong: shade_many lights them in batches
    const ShadowMaps* shadows_ = nullptr;      // null when no light casts shadows
    std::vector<const Material*> triangle_material_;  // per triangle, only when a mesh has several materials
    std::vector<size_t> shadowed_lights_;      // the scene lights with shadow maps
    std::vector<Light> unshadowed_lights_;     // flat and Gouraud with shadows: the others
    int terms_stride_ = 1;                     // flat and Gouraud: 1 + shadowed lights with shadows, else 1
    std::vector<LightingTerms> vertex_terms_;  // gouraud only: per global vertex, or per triangle corner (3 t + k)
                                               // when a mesh has several materials; terms_stride_ entries each
    std::vector<glm::vec3> corner_color_;      // gouraud without textures or shadows: per triangle corner (3 t + k),
                                               // the final colour base * diffuse + specular; shade_many interpolates
    std::vector<glm::vec3> face_color_;        // flat only: per triangle, final colour without texture or shadows
    std::vector<LightingTerms> face_terms_;    // flat with textures or shadows: per triangle, terms_stride_ entries
                                               // of base * diffuse and specular
    std::vector<glm::vec3> face_normal_;       // with shadows: per triangle, (b - a) x (c - a) in world space
    TextureLookup textures_;                   // textured scenes only
};

}  // namespace raster
