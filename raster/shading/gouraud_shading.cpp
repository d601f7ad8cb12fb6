// Gouraud shading: terms per vertex (or per triangle corner between materials), corner colours interpolated.
#include "raster/shading/gouraud_shading.h"

namespace raster {

GouraudShading::GouraudShading(const SurfaceLookup& surface) : surface_(surface), lighting_(surface) {
    const Scene& scene = surface.scene();
    const TransformedScene& geometry = surface.geometry();
    const size_t stride = lighting_.stride();
    auto light_vertex = [&](uint32_t vertex, const Material& material, LightingTerms* out) {
        lighting_.light(geometry.world_position[vertex], geometry.world_normal[vertex], material, out);
    };
    per_corner_ = surface.materials_per_triangle();
    if (per_corner_) {
        // A vertex between two materials is lit once for each: the terms are kept per triangle corner.
        vertex_terms_.resize(3 * geometry.triangles.size() * stride);
        for (uint32_t tri = 0; tri < geometry.triangles.size(); ++tri)
            for (int k = 0; k < 3; ++k)
                light_vertex(geometry.triangles[tri].v[k], surface.material(tri), &vertex_terms_[(3 * tri + k) * stride]);
    } else {
        vertex_terms_.resize(geometry.clip.size() * stride);
        for (uint32_t mesh = 0; mesh < scene.meshes.size(); ++mesh) {
            const uint32_t first = geometry.mesh_first_vertex[mesh];
            const size_t count = scene.meshes[mesh].data->positions.size();
            for (size_t i = first; i < first + count; ++i)
                light_vertex(static_cast<uint32_t>(i), scene.meshes[mesh].material, &vertex_terms_[i * stride]);
        }
    }
    if (!surface.textured() && !surface.shadowed()) {
        // Nothing varies per sample but the weights: each corner's final colour once per frame, as shade_point
        // forms it, so a sample is three products and two sums.
        corner_color_.resize(3 * geometry.triangles.size());
        for (uint32_t tri = 0; tri < geometry.triangles.size(); ++tri)
            for (int k = 0; k < 3; ++k) {
                glm::vec3 corner_bary(0.0f);
                corner_bary[k] = 1.0f;
                const LightingTerms& terms = *corner_terms(tri, k);
                corner_color_[3 * tri + k] = surface.base_color(tri, corner_bary) * terms.diffuse + terms.specular;
            }
    }
}

const LightingTerms* GouraudShading::corner_terms(uint32_t triangle, int corner) const {
    const size_t stride = lighting_.stride();
    if (per_corner_) return &vertex_terms_[(3 * triangle + corner) * stride];
    return &vertex_terms_[surface_.geometry().triangles[triangle].v[corner] * stride];
}

void GouraudShading::shade_many(const uint32_t* triangle, const glm::vec3* bary, size_t count, glm::vec3* out) const {
    if (!corner_color_.empty()) {  // shade_point's sum over the corners, in its order
        for (size_t j = 0; j < count; ++j) {
            const glm::vec3* corner = &corner_color_[3 * static_cast<size_t>(triangle[j])];
            const glm::vec3& b = bary[j];
            out[j] = glm::vec3(0.0f) + b[0] * corner[0] + b[1] * corner[1] + b[2] * corner[2];
        }
        return;
    }
    for (size_t j = 0; j < count; ++j) out[j] = shade_point(triangle[j], bary[j]);
}

glm::vec3 GouraudShading::shade_point(uint32_t triangle, const glm::vec3& bary) const {
    glm::vec3 texel(1.0f);
    const bool textured = surface_.texture_factor(triangle, bary, texel);
    const float* visibility = surface_.visibility_at(triangle, bary);
    // Each corner's colour is lit at the vertex, then the colours are interpolated. A face colour is constant over
    // the triangle, so base * interpolated terms is the same thing. A texture multiplies the interpolated
    // base * diffuse, not the highlight.
    glm::vec3 color(0.0f), diffuse(0.0f), highlight(0.0f);
    for (int i = 0; i < 3; ++i) {
        glm::vec3 corner_bary(0.0f);
        corner_bary[i] = 1.0f;
        const LightingTerms terms = lighting_.combined(corner_terms(triangle, i), visibility);
        if (textured) {
            diffuse += bary[i] * (surface_.base_color(triangle, corner_bary) * terms.diffuse);
            highlight += bary[i] * terms.specular;
        } else {
            color += bary[i] * (surface_.base_color(triangle, corner_bary) * terms.diffuse + terms.specular);
        }
    }
    return textured ? texel * diffuse + highlight : color;
}

}  // namespace raster
