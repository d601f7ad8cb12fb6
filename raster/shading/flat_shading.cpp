// Flat shading: per-face colours, or per-face terms that a texel and the shadows' visibility scale per sample.
#include "raster/shading/flat_shading.h"

#include <glm/geometric.hpp>

namespace raster {

FlatShading::FlatShading(const SurfaceLookup& surface) : surface_(surface), lighting_(surface) {
    const TransformedScene& geometry = surface.geometry();
    const size_t stride = lighting_.stride();
    const glm::vec3 centroid_bary(1.0f / 3.0f);
    const bool per_face_terms = surface.textured() || surface.shadowed();
    if (!per_face_terms) face_color_.resize(geometry.triangles.size());
    else face_terms_.resize(geometry.triangles.size() * stride);
    std::vector<LightingTerms> terms(stride);
    for (uint32_t tri = 0; tri < geometry.triangles.size(); ++tri) {
        const TriangleIndices& v = geometry.triangles[tri];
        const glm::vec3& a = geometry.world_position[v.v[0]];
        const glm::vec3& b = geometry.world_position[v.v[1]];
        const glm::vec3& c = geometry.world_position[v.v[2]];
        const glm::vec3 centroid = (a + b + c) / 3.0f;
        const glm::vec3 normal = unit_or_zero(glm::cross(b - a, c - a));
        lighting_.light(centroid, normal, surface.material(tri), terms.data());
        const glm::vec3 base = surface.base_color(tri, centroid_bary);
        if (!per_face_terms) face_color_[tri] = base * terms[0].diffuse + terms[0].specular;
        else
            for (size_t k = 0; k < stride; ++k) face_terms_[tri * stride + k] = {base * terms[k].diffuse, terms[k].specular};
    }
}

void FlatShading::shade_many(const uint32_t* triangle, const glm::vec3* bary, size_t count, glm::vec3* out) const {
    if (!face_color_.empty()) {  // one colour per triangle
        for (size_t j = 0; j < count; ++j) out[j] = face_color_[triangle[j]];
        return;
    }
    for (size_t j = 0; j < count; ++j) out[j] = shade_point(triangle[j], bary[j]);
}

glm::vec3 FlatShading::shade_point(uint32_t triangle, const glm::vec3& bary) const {
    glm::vec3 texel(1.0f);
    const bool textured = surface_.texture_factor(triangle, bary, texel);
    const float* visibility = surface_.visibility_at(triangle, bary);
    const LightingTerms terms = lighting_.combined(&face_terms_[triangle * lighting_.stride()], visibility);
    return (textured ? texel * terms.diffuse : terms.diffuse) + terms.specular;
}

}  // namespace raster
