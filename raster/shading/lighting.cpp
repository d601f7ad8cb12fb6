// Lighting of one point: Blinn-Phong and Phong through the batch kernels, and the per-light parts the stylized modes use.
#include "raster/shading/lighting.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "raster/core/unit_vector.h"

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
    const bool directional = light.type == LightType::directional;
    glm::vec3 to_light = directional ? directional_to_light(light) : light.position - position;
    float distance_squared = 1.0f;
    if (!directional) {
        distance_squared = glm::dot(to_light, to_light);
        if (!(distance_squared > 0.0f)) return false;
        to_light /= std::sqrt(distance_squared);
    }
    const float n_dot_l = glm::dot(normal, to_light);
    if (n_dot_l <= 0.0f) return false;
    glm::vec3 radiance = light.color * light.intensity;
    if (light.type == LightType::spot) radiance *= spot_factor(light, to_light);
    if (light.attenuate && !directional) radiance /= distance_squared;
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
    thread_local LightingBatch batch;  // lanes past the first hold stale points, computed and ignored
    thread_local std::vector<float> visibility_rows;
    for (int c = 0; c < 3; ++c) {
        batch.position[c][0] = position[c];
        batch.normal[c][0] = normal[c];
        batch.to_eye[c][0] = to_eye[c];
    }
    if (visibility) {
        visibility_rows.resize(lights.size() * LightingBatch::kRow);
        for (size_t k = 0; k < lights.size(); ++k) visibility_rows[k * LightingBatch::kRow] = visibility[k];
    }
    light_points(batch, 0, 1, material, lights, ambient_light, model, visibility ? visibility_rows.data() : nullptr);
    LightingTerms terms;
    for (int c = 0; c < 3; ++c) {
        terms.diffuse[c] = batch.diffuse[c][0];
        terms.specular[c] = batch.specular[c][0];
    }
    return terms;
}

}  // namespace raster
