// Cel and Gooch lighting (stylized_lighting.h).
#include "raster/shading/stylized_lighting.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace raster {

float cel_band(float n_dot_l, int bands) {
    const float count = static_cast<float>(bands);
    return std::min(std::ceil(n_dot_l * count), count) / count;
}

LightingTerms evaluate_cel_lighting(const glm::vec3& position, const glm::vec3& normal, const glm::vec3& to_eye,
                                    const Material& material, const std::vector<Light>& lights,
                                    const glm::vec3& ambient_light, int bands, const float* visibility) {
    LightingTerms terms;
    terms.diffuse = material.ambient * ambient_light;
    for (size_t index = 0; index < lights.size(); ++index) {
        const float visible = visibility ? visibility[index] : 1.0f;
        LightArrival arrival;
        if (visible == 0.0f || !light_arrives(lights[index], position, normal, arrival)) continue;
        terms.diffuse += arrival.radiance * material.diffuse * cel_band(arrival.n_dot_l * visible, bands);
        const float lobe = blinn_lobe(normal, arrival.to_light, to_eye);
        if (lobe > 0.0f && specular_power(lobe, material.exponent) * visible >= 0.5f)
            terms.specular += arrival.radiance * material.specular;
    }
    return terms;
}

LightingTerms evaluate_gooch_lighting(const glm::vec3& position, const glm::vec3& normal, const glm::vec3& to_eye,
                                      const Material& material, const std::vector<Light>& lights,
                                      const GoochTones& tones, const float* visibility) {
    float t = 0.5f;
    LightingTerms terms;
    if (!lights.empty()) {
        const Light& key = lights.front();
        const float visible = visibility ? visibility[0] : 1.0f;
        if (key.type == LightType::directional) {
            t = 0.5f * (1.0f + glm::dot(normal, directional_to_light(key))) * visible;
        } else {
            const glm::vec3 offset = key.position - position;
            const float distance = glm::length(offset);
            if (distance > 0.0f) t = 0.5f * (1.0f + glm::dot(normal, offset / distance)) * visible;
        }
        LightArrival arrival;
        if (light_arrives(key, position, normal, arrival)) {
            const float lobe = blinn_lobe(normal, arrival.to_light, to_eye);
            terms.specular = arrival.radiance * material.specular * highlight_of(lobe, material.exponent) * visible;
        }
    }
    terms.diffuse = material.diffuse * (tones.alpha + t * (tones.beta - tones.alpha));
    terms.specular += t * glm::vec3(tones.yellow, tones.yellow, 0.0f) + (1.0f - t) * glm::vec3(0.0f, 0.0f, tones.blue);
    return terms;
}

}  // namespace raster
