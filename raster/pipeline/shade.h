// Shading: the colour of a visible point from its triangle id and barycentrics. Shared by the rasterizer and
// the oracle, so both colour their visibility buffers with the same function.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "raster/pipeline/texture_lookup.h"
#include "raster/pipeline/vertex_stage.h"
#include "raster/scene/scene.h"

namespace raster {

// The lit result before the base colour is applied: colour = base * diffuse + specular.
// `diffuse` already includes the ambient term.
struct LightingTerms {
    glm::vec3 diffuse{0.0f};
    glm::vec3 specular{0.0f};
};

enum class SpecularModel { blinn, phong };

// What one point light gives a surface point: the unit direction to it, n.l, and its radiance (colour times
// intensity, over r^2 with attenuation).
struct LightArrival {
    glm::vec3 to_light{0.0f};
    float n_dot_l = 0.0f;
    glm::vec3 radiance{0.0f};
};
// False when the light adds nothing: it sits on the point, or lies behind the surface (n.l <= 0; one-sided).
bool light_arrives(const Light& light, const glm::vec3& position, const glm::vec3& normal, LightArrival& out);

// Blinn's lobe n.h, h the normalised half vector of the unit vectors to the light and to the eye (0 when they are
// opposite).
float blinn_lobe(const glm::vec3& normal, const glm::vec3& to_light, const glm::vec3& to_eye);

// The highlight max(0, lobe)^exponent, with 0^0 = 1 (an exponent of 0 lights every point fully).
float highlight_of(float lobe, float exponent);

// Ambient plus, for each light, Lambert diffuse and a specular lobe, with optional 1/r^2 attenuation. Lighting is
// one-sided: a light behind the surface (n.l <= 0) adds nothing. `normal` must be unit length; `to_eye` is the
// unit vector from the point to the eye.
LightingTerms evaluate_lighting(const glm::vec3& position, const glm::vec3& normal, const glm::vec3& to_eye,
                                const Material& material, const std::vector<Light>& lights,
                                const glm::vec3& ambient_light, SpecularModel model);

// The signature of evaluate_lighting, so a pipeline can be given another lighting model.
// base^exponent for the specular highlight: by repeated squaring for integer exponents n in [0, 256] (relative error
// at most about n 2^-24, invisible in 8-bit output), std::pow otherwise.
float specular_power(float base, float exponent);

using LightingFunction = LightingTerms (*)(const glm::vec3&, const glm::vec3&, const glm::vec3&, const Material&,
                                           const std::vector<Light>&, const glm::vec3&, SpecularModel);

// Everything shading needs, prepared once per frame for the scene's shading mode: per-vertex lit terms for
// Gouraud, per-face colours for flat, texture coordinates and gradients for textured triangles, nothing extra
// for unlit. Holds pointers into `scene` and `geometry`, which must outlive it.
class Shader {
public:
    Shader(const Scene& scene, const TransformedScene& geometry, LightingFunction lighting = evaluate_lighting);

    // Linear RGB of triangle `triangle` at barycentrics `bary` (w.r.t. its original vertices), unclamped.
    glm::vec3 shade(uint32_t triangle, const glm::vec3& bary) const;

private:
    // The face colour, else the interpolated vertex colour, else the material colour; no texture.
    glm::vec3 base_color(uint32_t triangle, const glm::vec3& bary) const;
    // The texture's value at the point when the triangle's material has one (it multiplies the base colour).
    bool texture_factor(uint32_t triangle, const glm::vec3& bary, glm::vec3& factor) const;
    const Material& material(uint32_t triangle) const;
    LightingTerms light_at(uint32_t triangle, const glm::vec3& bary) const;
    const LightingTerms& corner_terms(uint32_t triangle, int corner) const;

    const Scene& scene_;
    const TransformedScene& geometry_;
    ShadingMode mode_;
    LightingFunction lighting_;
    std::vector<const Material*> triangle_material_;  // per triangle, only when a mesh has several materials
    std::vector<LightingTerms> vertex_terms_;  // gouraud only: per global vertex, or per triangle corner (3 t + k)
                                               // when a mesh has several materials
    std::vector<glm::vec3> face_color_;        // flat only: per triangle, final colour without texture
    std::vector<LightingTerms> face_terms_;    // flat with textures only: per triangle, base * diffuse, specular
    TextureLookup textures_;                   // textured scenes only
};

}  // namespace raster
