// The surface lookup: materials, base colours, textures, corners and shadow visibility of a frame's triangles.
#include "raster/shading/surface.h"

#include <algorithm>

#include <glm/geometric.hpp>

#include "raster/shading/shadow_maps.h"
#include "raster/texture/texture_sampler.h"

namespace raster {
namespace {

bool any_mesh_has_parts(const Scene& scene) {
    return std::any_of(scene.meshes.begin(), scene.meshes.end(), [](const SceneMesh& m) { return !m.parts.empty(); });
}

}  // namespace

SurfaceLookup::SurfaceLookup(const Scene& scene, const TransformedScene& geometry, const ShadowMaps* shadows)
    : scene_(scene), geometry_(geometry) {
    if (any_mesh_has_parts(scene)) {
        triangle_material_.resize(geometry.triangles.size());
        for (uint32_t tri = 0; tri < geometry.triangles.size(); ++tri) {
            const uint32_t mesh = geometry.triangle_mesh[tri];
            triangle_material_[tri] = &material_of(scene.meshes[mesh], tri - geometry.mesh_first_triangle[mesh]);
        }
    }
    if (has_textures(scene)) textures_ = TextureLookup(scene, geometry);
    if (shadows && !shadows->empty() && scene.settings.shading != ShadingMode::unlit) {
        shadows_ = shadows;
        for (size_t light = 0; light < scene.lights.size(); ++light) {
            if (shadows->casts(light)) shadowed_lights_.push_back(light);
            else unshadowed_lights_.push_back(scene.lights[light]);
        }
        face_normal_.resize(geometry.triangles.size());
        for (uint32_t tri = 0; tri < geometry.triangles.size(); ++tri) {
            const TriangleIndices& v = geometry.triangles[tri];
            const glm::vec3& a = geometry.world_position[v.v[0]];
            face_normal_[tri] = glm::cross(geometry.world_position[v.v[1]] - a, geometry.world_position[v.v[2]] - a);
        }
    }
}

bool SurfaceLookup::texture_factor(uint32_t triangle, const glm::vec3& bary, glm::vec3& factor) const {
    if (textures_.empty()) return false;
    const Material& m = material(triangle);
    if (!m.texture) return false;
    const TexturePoint point = textures_.at(triangle, bary);
    factor = sample_texture(*m.texture->texture, sampler_of(*m.texture, scene_.settings.texture_filter), point.uv,
                            point.duv_dx, point.duv_dy);
    return true;
}

float SurfaceLookup::opacity(uint32_t triangle, const glm::vec3& bary) const {
    const Material& m = material(triangle);
    if (!m.texture || !m.texture->reads_alpha) return m.opacity;
    const TexturePoint point = textures_.at(triangle, bary);
    const float texel_alpha = sample_texture(*m.texture->alpha_texture, sampler_of(*m.texture, scene_.settings.texture_filter),
                                             point.uv, point.duv_dx, point.duv_dy).x;
    const float alpha = m.opacity * texel_alpha;
    if (!m.alpha_cutoff) return alpha;
    return alpha >= *m.alpha_cutoff ? 1.0f : 0.0f;
}

glm::vec3 SurfaceLookup::lit_color(uint32_t triangle, const glm::vec3& bary, const glm::vec3* texel,
                                   const LightingTerms& terms) const {
    return lit(texel ? base_color(triangle, bary) * *texel : base_color(triangle, bary), terms);
}

const float* SurfaceLookup::visibility_at(uint32_t triangle, const glm::vec3& bary) const {
    if (!shadows_) return nullptr;
    thread_local std::vector<float> visibility;
    visibility.assign(scene_.lights.size(), 1.0f);
    const TriangleIndices& v = geometry_.triangles[triangle];
    glm::vec3 position(0.0f);
    for (int i = 0; i < 3; ++i) position += bary[i] * geometry_.world_position[v.v[i]];
    shadow_visibility(triangle, position, visibility.data(), 1);
    return visibility.data();
}

void SurfaceLookup::shadow_visibility(uint32_t triangle, const glm::vec3& position, float* out, size_t stride) const {
    for (size_t light : shadowed_lights_)
        out[light * stride] = shadows_->visibility(light, position, face_normal_[triangle]);
}

}  // namespace raster
