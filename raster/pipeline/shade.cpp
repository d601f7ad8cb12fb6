// Shading: Blinn-Phong and Phong lighting, evaluated per face (flat), per vertex (Gouraud) or per sample.
#include "raster/pipeline/shade.h"

#include <cmath>

#include <glm/geometric.hpp>

namespace raster {

float specular_power(float base, float exponent) {
    if (exponent >= 0.0f && exponent <= 256.0f && exponent == std::floor(exponent)) {
        // Square and multiply: at most 16 multiplications for an integer exponent, several times faster than powf
        // (most scenes' exponents are integers); relative error at most about n 2^-24 (shade.h).
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

LightingTerms evaluate_lighting(const glm::vec3& position, const glm::vec3& normal, const glm::vec3& to_eye,
                                const Material& material, const std::vector<Light>& lights,
                                const glm::vec3& ambient_light, SpecularModel model) {
    LightingTerms terms;
    terms.diffuse = material.ambient * ambient_light;
    for (const Light& light : lights) {
        glm::vec3 to_light = light.position - position;
        const float distance_squared = glm::dot(to_light, to_light);
        if (!(distance_squared > 0.0f)) continue;
        to_light /= std::sqrt(distance_squared);
        const float n_dot_l = glm::dot(normal, to_light);
        if (n_dot_l <= 0.0f) continue;
        glm::vec3 radiance = light.color * light.intensity;
        if (light.attenuate) radiance /= distance_squared;
        float lobe;
        if (model == SpecularModel::blinn) {
            const glm::vec3 half = to_light + to_eye;
            const float half_length_squared = glm::dot(half, half);
            lobe = half_length_squared > 0.0f ? glm::dot(normal, half) / std::sqrt(half_length_squared) : 0.0f;
        } else {
            const glm::vec3 reflected = 2.0f * n_dot_l * normal - to_light;
            lobe = glm::dot(reflected, to_eye);
        }
        terms.diffuse += radiance * material.diffuse * n_dot_l;
        // lobe^exponent with max(0, lobe); pow is skipped where it is 0 (and 0^0 = 1 kept for exponent 0).
        const float highlight = lobe > 0.0f ? specular_power(lobe, material.exponent) : (material.exponent == 0.0f ? 1.0f : 0.0f);
        terms.specular += radiance * material.specular * highlight;
    }
    return terms;
}

namespace {

glm::vec3 unit_or_zero(const glm::vec3& v) {
    const float length = glm::length(v);
    return length > 0.0f ? v / length : glm::vec3(0.0f);
}

}  // namespace

Shader::Shader(const Scene& scene, const TransformedScene& geometry, LightingFunction lighting)
    : scene_(scene), geometry_(geometry), mode_(scene.settings.shading), lighting_(lighting) {
    if (mode_ == ShadingMode::gouraud) {
        vertex_terms_.resize(geometry.clip.size());
        for (uint32_t mesh = 0; mesh < scene.meshes.size(); ++mesh) {
            const uint32_t first = geometry.mesh_first_vertex[mesh];
            const size_t count = scene.meshes[mesh].data.positions.size();
            for (size_t i = first; i < first + count; ++i) {
                const glm::vec3& p = geometry.world_position[i];
                vertex_terms_[i] = lighting_(p, geometry.world_normal[i], unit_or_zero(scene.camera.eye - p),
                                                     scene.meshes[mesh].material, scene.lights,
                                                     scene.settings.ambient_light, SpecularModel::blinn);
            }
        }
    } else if (mode_ == ShadingMode::flat) {
        const glm::vec3 centroid_bary(1.0f / 3.0f);
        face_color_.resize(geometry.triangles.size());
        for (uint32_t tri = 0; tri < geometry.triangles.size(); ++tri) {
            const TriangleIndices& v = geometry.triangles[tri];
            const glm::vec3& a = geometry.world_position[v.v[0]];
            const glm::vec3& b = geometry.world_position[v.v[1]];
            const glm::vec3& c = geometry.world_position[v.v[2]];
            const glm::vec3 centroid = (a + b + c) / 3.0f;
            const glm::vec3 normal = unit_or_zero(glm::cross(b - a, c - a));
            const LightingTerms terms =
                lighting_(centroid, normal, unit_or_zero(scene.camera.eye - centroid),
                                  scene.meshes[geometry.triangle_mesh[tri]].material, scene.lights,
                                  scene.settings.ambient_light, SpecularModel::blinn);
            face_color_[tri] = base_color(tri, centroid_bary) * terms.diffuse + terms.specular;
        }
    }
}

glm::vec3 Shader::base_color(uint32_t triangle, const glm::vec3& bary) const {
    const uint32_t mesh_index = geometry_.triangle_mesh[triangle];
    const MeshData& mesh = scene_.meshes[mesh_index].data;
    const uint32_t local = triangle - geometry_.mesh_first_triangle[mesh_index];
    if (!mesh.face_colors.empty()) return mesh.face_colors[local];
    if (!mesh.colors.empty()) {
        const TriangleIndices& v = mesh.triangles[local];
        return bary.x * mesh.colors[v.v[0]] + bary.y * mesh.colors[v.v[1]] + bary.z * mesh.colors[v.v[2]];
    }
    return scene_.meshes[mesh_index].material.color;
}

glm::vec3 Shader::shade(uint32_t triangle, const glm::vec3& bary) const {
    switch (mode_) {
        case ShadingMode::unlit:
            return base_color(triangle, bary);
        case ShadingMode::flat:
            return face_color_[triangle];
        case ShadingMode::gouraud: {
            // Each corner's colour is lit at the vertex, then the colours are interpolated. A face colour is
            // constant over the triangle, so base * interpolated terms is the same thing.
            const TriangleIndices& v = geometry_.triangles[triangle];
            glm::vec3 color(0.0f);
            for (int i = 0; i < 3; ++i) {
                glm::vec3 corner_bary(0.0f);
                corner_bary[i] = 1.0f;
                const LightingTerms& terms = vertex_terms_[v.v[i]];
                color += bary[i] * (base_color(triangle, corner_bary) * terms.diffuse + terms.specular);
            }
            return color;
        }
        case ShadingMode::phong:
        case ShadingMode::blinn_phong: {
            const TriangleIndices& v = geometry_.triangles[triangle];
            glm::vec3 position(0.0f), normal(0.0f);
            for (int i = 0; i < 3; ++i) {
                position += bary[i] * geometry_.world_position[v.v[i]];
                normal += bary[i] * geometry_.world_normal[v.v[i]];
            }
            const LightingTerms terms = lighting_(
                position, unit_or_zero(normal), unit_or_zero(scene_.camera.eye - position),
                scene_.meshes[geometry_.triangle_mesh[triangle]].material, scene_.lights,
                scene_.settings.ambient_light,
                mode_ == ShadingMode::phong ? SpecularModel::phong : SpecularModel::blinn);
            return base_color(triangle, bary) * terms.diffuse + terms.specular;
        }
    }
    return glm::vec3(0.0f);
}

}  // namespace raster
