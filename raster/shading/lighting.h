// Lighting: what the scene's point lights give a surface point under Blinn-Phong or Phong (per light: Lambert
// diffuse and a specular lobe), each light's part scaled by its visibility from the shadow maps.
#pragma once

#include <vector>

#include <glm/vec3.hpp>

#include "raster/shading/light_direction.h"
#include "raster/shading/lighting_kernels.h"
#include "raster/scene/scene.h"

namespace raster {

// The lit result before the base colour is applied: colour = base * diffuse + specular.
// `diffuse` already includes the ambient term.
struct LightingTerms {
    glm::vec3 diffuse{0.0f};
    glm::vec3 specular{0.0f};
};

// The colour of a point of base colour `base` under `terms`.
inline glm::vec3 lit(const glm::vec3& base, const LightingTerms& terms) { return base * terms.diffuse + terms.specular; }

// What one point light gives a surface point: the unit direction to it, n.l, and its radiance (colour times
// intensity, over r^2 with attenuation).
struct LightArrival {
    glm::vec3 to_light{0.0f};
    float n_dot_l = 0.0f;
    glm::vec3 radiance{0.0f};
};
// False when the light adds nothing: it sits on the point, or lies behind the surface (n.l <= 0; one-sided).
// The radiance is colour x intensity, times a spot light's fade, divided by r^2 for an attenuated point or spot.
bool light_arrives(const Light& light, const glm::vec3& position, const glm::vec3& normal, LightArrival& out);


// Blinn's lobe n.h, h the normalised half vector of the unit vectors to the light and to the eye (0 when they are
// opposite).
float blinn_lobe(const glm::vec3& normal, const glm::vec3& to_light, const glm::vec3& to_eye);

// The highlight max(0, lobe)^exponent, with 0^0 = 1 (an exponent of 0 lights every point fully).
float highlight_of(float lobe, float exponent);

// base^exponent for the specular highlight: by repeated squaring for integer exponents n in [0, 256] (relative error
// at most about n 2^-24, invisible in 8-bit output), std::pow otherwise.
float specular_power(float base, float exponent);

// Ambient plus, for each light, Lambert diffuse and a specular lobe, with optional 1/r^2 attenuation, each light's
// part times its visibility (visibility[i] for lights[i], in [0, 1]: the shadow maps' answer; null: every light
// fully visible). One point through the lighting kernels (lighting_kernels.h): the same bits as a batch gives it.
// Lighting is one-sided: a light behind the surface (n.l <= 0) adds nothing. `normal` must be unit
// length; `to_eye` is the unit vector from the point to the eye.
LightingTerms evaluate_lighting(const glm::vec3& position, const glm::vec3& normal, const glm::vec3& to_eye,
                                const Material& material, const std::vector<Light>& lights,
                                const glm::vec3& ambient_light, SpecularModel model, const float* visibility);

}  // namespace raster
