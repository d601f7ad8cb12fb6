// Blinn-Phong and Phong lighting per point light, with one-sided Lambert diffuse and optional 1/r^2 attenuation.
#include "raster/pipeline/lighting.h"

#include <cmath>

#include <glm/geometric.hpp>

namespace raster {

float specular_power(float base, float exponent) {
    if (exponent >= 0.0f && exponent <= 256.0f && exponent == std::floor(exponent)) {
        // Square and multiply: at most 16 multiplications for an integer exponent, several times faster than powf
        // (most scenes' exponents are integers); relative error at most about n 2^-24 (lighting.h).
        unsigned n = static_cast<unsigned>(exponent);
        float result = 1.0f, square = base;
        while (n) {
            if (n & 1u) result *= square;
            n >>= 1;
            if (n) square *= square;
        }
        return result;
    }
    return std::pow(base, exponent);
}

bool light_arrives(const Light& light, const glm::vec3& position, const glm::vec3& normal, LightArrival& out) {
    glm::vec3 to_light = light.position - position;
    const float distance_squared = glm::dot(to_light, to_light);
    if (!(distance_squared > 0.0f)) return false;
    to_light /= std::sqrt(distance_squared);
    const float n_dot_l = glm::dot(normal, to_light);
    if (n_dot_l <= 0.0f) return false;
    glm::vec3 radiance = light.color * light.intensity;
    if (light.attenuate) radiance /= distance_squared;
    out = {to_light, n_dot_l, radiance};
    return true;
}

float blinn_lobe(const glm::vec3& normal, const glm::vec3& to_light, const glm::vec3& to_eye) {
    const glm::vec3 half = to_light + to_eye;
    const float half_length_squared = glm::dot(half, half);
    const float lobe = half_length_squared > 0.0f ? glm::dot(normal, half) / std::sqrt(half_length_squared) : 0.0f;
    return lobe;
}

float highlight_of(float lobe, float exponent) {
    // lobe^exponent with max(0, lobe); pow is skipped where it is 0 (and 0^0 = 1 kept for exponent 0).
    const float highlight = lobe > 0.0f ? specular_power(lobe, exponent) : (exponent == 0.0f ? 1.0f : 0.0f);
    return highlight;
}

LightingTerms evaluate_lighting(const glm::vec3& position, const glm::vec3& normal, const glm::vec3& to_eye,
                                const Material& material, const std::vector<Light>& lights,
                                const glm::vec3& ambient_light, SpecularModel model, const float* visibility) {
    LightingTerms terms;
    terms.diffuse = material.ambient * ambient_light;
    for (size_t index = 0; index < lights.size(); ++index) {
        const Light& light = lights[index];
        const float visible = visibility ? visibility[index] : 1.0f;
        if (visible == 0.0f) continue;  // in shadow: the light adds nothing
        LightArrival arrival;
        if (!light_arrives(light, position, normal, arrival)) continue;
        const auto& [to_light, n_dot_l, radiance] = arrival;
        float lobe;
        if (model == SpecularModel::blinn) {
            lobe = blinn_lobe(normal, to_light, to_eye);
        } else {
            const glm::vec3 reflected = 2.0f * n_dot_l * normal - to_light;
            lobe = glm::dot(reflected, to_eye);
        }
        terms.diffuse += radiance * material.diffuse * n_dot_l * visible;
        terms.specular += radiance * material.specular * highlight_of(lobe, material.exponent) * visible;
    }
    return terms;
}

}  // namespace raster
