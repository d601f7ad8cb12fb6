// Shading: Blinn-Phong and Phong lighting, evaluated per face (flat), per vertex (Gouraud) or per sample.
#include "raster/pipeline/shade.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "raster/pipeline/stylized_lighting.h"
#include "raster/texture/texture_sampler.h"

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
                                const glm::vec3& ambient_light, SpecularModel model) {
    LightingTerms terms;
    terms.diffuse = material.ambient * ambient_light;
    for (const Light& light : lights) {
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
        terms.diffuse += radiance * material.diffuse * n_dot_l;
        terms.specular += radiance * material.specular * highlight_of(lobe, material.exponent);
    }
    return terms;
}

namespace {

glm::vec3 unit_or_zero(const glm::vec3& v) {
    const float length = glm::length(v);
    return length > 0.0f ? v / length : glm::vec3(0.0f);
}

bool any_mesh_has_parts(const Scene& scene) {
    return std::any_of(scene.meshes.begin(), scene.meshes.end(), [](const SceneMesh& m) { return !m.parts.empty(); });
}

}  // namespace

Shader::Shader(const Scene& scene, const TransformedScene& geometry, LightingFunction lighting)
    : scene_(scene), geometry_(geometry), mode_(scene.settings.shading), lighting_(lighting) {
    if (any_mesh_has_parts(scene)) {
        triangle_material_.resize(geometry.triangles.size());
        for (uint32_t tri = 0; tri < geometry.triangles.size(); ++tri) {
            const uint32_t mesh = geometry.triangle_mesh[tri];
            triangle_material_[tri] = &material_of(scene.meshes[mesh], tri - geometry.mesh_first_triangle[mesh]);
        }
    }
    const bool textured = has_textures(scene);
    if (textured) textures_ = TextureLookup(scene, geometry);
    if (mode_ == ShadingMode::gouraud) {
        auto light_vertex = [&](uint32_t vertex, const Material& material) {
            const glm::vec3& p = geometry.world_position[vertex];
            return lighting_(p, geometry.world_normal[vertex], unit_or_zero(scene.camera.eye - p), material,
                             scene.lights, scene.settings.ambient_light, SpecularModel::blinn);
        };
        if (!triangle_material_.empty()) {
            // A vertex between two materials is lit once for each: the terms are kept per triangle corner.
            vertex_terms_.resize(3 * geometry.triangles.size());
            for (uint32_t tri = 0; tri < geometry.triangles.size(); ++tri)
                for (int k = 0; k < 3; ++k)
                    vertex_terms_[3 * tri + k] = light_vertex(geometry.triangles[tri].v[k], *triangle_material_[tri]);
        } else {
            vertex_terms_.resize(geometry.clip.size());
            for (uint32_t mesh = 0; mesh < scene.meshes.size(); ++mesh) {
                const uint32_t first = geometry.mesh_first_vertex[mesh];
                const size_t count = scene.meshes[mesh].data.positions.size();
                for (size_t i = first; i < first + count; ++i)
                    vertex_terms_[i] = light_vertex(static_cast<uint32_t>(i), scene.meshes[mesh].material);
            }
        }
    } else if (mode_ == ShadingMode::flat) {
        const glm::vec3 centroid_bary(1.0f / 3.0f);
        face_color_.resize(geometry.triangles.size());
        if (textured) face_terms_.resize(geometry.triangles.size());
        for (uint32_t tri = 0; tri < geometry.triangles.size(); ++tri) {
            const TriangleIndices& v = geometry.triangles[tri];
            const glm::vec3& a = geometry.world_position[v.v[0]];
            const glm::vec3& b = geometry.world_position[v.v[1]];
            const glm::vec3& c = geometry.world_position[v.v[2]];
            const glm::vec3 centroid = (a + b + c) / 3.0f;
            const glm::vec3 normal = unit_or_zero(glm::cross(b - a, c - a));
            const LightingTerms terms =
                lighting_(centroid, normal, unit_or_zero(scene.camera.eye - centroid), material(tri), scene.lights,
                          scene.settings.ambient_light, SpecularModel::blinn);
            face_color_[tri] = base_color(tri, centroid_bary) * terms.diffuse + terms.specular;
            if (textured) face_terms_[tri] = {base_color(tri, centroid_bary) * terms.diffuse, terms.specular};
        }
    }
}

const Material& Shader::material(uint32_t triangle) const {
    if (!triangle_material_.empty()) return *triangle_material_[triangle];
    return scene_.meshes[geometry_.triangle_mesh[triangle]].material;
}

const LightingTerms& Shader::corner_terms(uint32_t triangle, int corner) const {
    if (!triangle_material_.empty()) return vertex_terms_[3 * triangle + corner];
    return vertex_terms_[geometry_.triangles[triangle].v[corner]];
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
    return material(triangle).color;
}

bool Shader::texture_factor(uint32_t triangle, const glm::vec3& bary, glm::vec3& factor) const {
    if (textures_.empty()) return false;
    const Material& m = material(triangle);
    if (!m.texture) return false;
    const TexturePoint point = textures_.at(triangle, bary);
    factor = sample_texture(*m.texture->texture, sampler_of(*m.texture, scene_.settings.texture_filter), point.uv,
                            point.duv_dx, point.duv_dy);
    return true;
}

LightingTerms Shader::light_at(uint32_t triangle, const glm::vec3& bary) const {
    const TriangleIndices& v = geometry_.triangles[triangle];
    glm::vec3 position(0.0f), normal(0.0f);
    for (int i = 0; i < 3; ++i) {
        position += bary[i] * geometry_.world_position[v.v[i]];
        normal += bary[i] * geometry_.world_normal[v.v[i]];
    }
    const glm::vec3 unit_normal = unit_or_zero(normal), to_eye = unit_or_zero(scene_.camera.eye - position);
    const RenderSettings& settings = scene_.settings;
    switch (mode_) {
        case ShadingMode::cel:
            return evaluate_cel_lighting(position, unit_normal, to_eye, material(triangle), scene_.lights,
                                         settings.ambient_light, settings.cel_bands);
        case ShadingMode::gooch:
            return evaluate_gooch_lighting(position, unit_normal, to_eye, material(triangle), scene_.lights,
                                           settings.gooch);
        default:
            return lighting_(position, unit_normal, to_eye, material(triangle), scene_.lights, settings.ambient_light,
                             mode_ == ShadingMode::phong ? SpecularModel::phong : SpecularModel::blinn);
    }
}

glm::vec3 Shader::shade(uint32_t triangle, const glm::vec3& bary) const {
    glm::vec3 texel(1.0f);
    const bool textured = texture_factor(triangle, bary, texel);
    switch (mode_) {
        case ShadingMode::unlit:
            return textured ? base_color(triangle, bary) * texel : base_color(triangle, bary);
        case ShadingMode::flat:
            if (textured) return texel * face_terms_[triangle].diffuse + face_terms_[triangle].specular;
            return face_color_[triangle];
        case ShadingMode::gouraud: {
            // Each corner's colour is lit at the vertex, then the colours are interpolated. A face colour is
            // constant over the triangle, so base * interpolated terms is the same thing. A texture multiplies the
            // interpolated base * diffuse, not the highlight.
            glm::vec3 color(0.0f), lit(0.0f), highlight(0.0f);
            for (int i = 0; i < 3; ++i) {
                glm::vec3 corner_bary(0.0f);
                corner_bary[i] = 1.0f;
                const LightingTerms& terms = corner_terms(triangle, i);
                if (textured) {
                    lit += bary[i] * (base_color(triangle, corner_bary) * terms.diffuse);
                    highlight += bary[i] * terms.specular;
                } else {
                    color += bary[i] * (base_color(triangle, corner_bary) * terms.diffuse + terms.specular);
                }
            }
            return textured ? texel * lit + highlight : color;
        }
        case ShadingMode::phong:
        case ShadingMode::blinn_phong:
        case ShadingMode::cel:
        case ShadingMode::gooch: {
            const LightingTerms terms = light_at(triangle, bary);
            const glm::vec3 base = textured ? base_color(triangle, bary) * texel : base_color(triangle, bary);
            return base * terms.diffuse + terms.specular;
        }
    }
    return glm::vec3(0.0f);
}

}  // namespace raster
