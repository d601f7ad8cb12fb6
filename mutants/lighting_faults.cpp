// The lighting stage's faulty variant of the bug catalogue, around the real evaluate_lighting.
#include "mutants/lighting_faults.h"

namespace raster::mutants {

// "1/r^2 attenuation missing": lights marked as attenuating shine as if they were not.
LightingTerms lighting_without_attenuation(const glm::vec3& position, const glm::vec3& normal, const glm::vec3& to_eye,
                                           const Material& material, const std::vector<Light>& lights,
                                           const glm::vec3& ambient_light, SpecularModel model) {
    std::vector<Light> unattenuated = lights;
    for (Light& light : unattenuated) light.attenuate = false;
    return evaluate_lighting(position, normal, to_eye, material, unattenuated, ambient_light, model);
}

}  // namespace raster::mutants
