// Non-photorealistic lighting: cel (toon) bands and Gooch et al.'s cool-to-warm tones, in the same
// base * diffuse + specular form as Blinn-Phong, so a texture or vertex colour multiplies them alike.
#pragma once

#include <vector>

#include <glm/vec3.hpp>

#include "raster/shading/lighting.h"
#include "raster/scene/scene.h"

namespace raster {

// n.l in (0, 1] to its band: ceil(n.l bands) / bands, so the band edges sit at n.l = k / bands, a lit point is
// at least 1 / bands bright and a point facing the light is at full strength.
float cel_band(float n_dot_l, int bands);

// Cel: ambient, plus per light its diffuse at the banded n.l, plus a hard-edged highlight: the light's specular in
// full where Blinn's (n.h)^exponent >= 1/2, none elsewhere. No outlines. A light's visibility v (visibility[i] for
// lights[i]; null: 1) scales what is banded and thresholded: the band of v n.l, the highlight where v (n.h)^e >= 1/2.
LightingTerms evaluate_cel_lighting(const glm::vec3& position, const glm::vec3& normal, const glm::vec3& to_eye,
                                    const Material& material, const std::vector<Light>& lights,
                                    const glm::vec3& ambient_light, int bands, const float* visibility);

// Gooch: with t = (1 + n.l) / 2 toward the scene's first light (t = 1/2 with no light, n.l not clamped),
//   colour = t k_warm + (1 - t) k_cool + the first light's Blinn highlight
// (GoochTones in scene.h), which is base * diffuse (alpha + t (beta - alpha)) + t (y, y, 0) + (1 - t) (0, 0, b)
// + specular. No ambient term: the tones take its place. Light colour and intensity scale only the highlight.
// The first light's visibility v (visibility[0]; null: 1) scales t and the highlight: a point in its shadow takes
// the cool tone.
LightingTerms evaluate_gooch_lighting(const glm::vec3& position, const glm::vec3& normal, const glm::vec3& to_eye,
                                      const Material& material, const std::vector<Light>& lights,
                                      const GoochTones& tones, const float* visibility);

}  // namespace raster
