// Blinn-Phong and Phong shading in batches: points interpolated, oriented, shadowed and lit by the kernels.
#include "raster/shading/blinn_phong_shading.h"

#include <algorithm>
#include <vector>

namespace raster {

BlinnPhongShading::BlinnPhongShading(const SurfaceLookup& surface, SpecularModel specular)
    : surface_(surface), specular_(specular) {}

void BlinnPhongShading::light_batch(const uint32_t* triangle, const glm::vec3* bary, size_t count,
                                    LightingBatch& batch) const {
    const Scene& scene = surface_.scene();
    // Each run of points on one triangle reads its corners once.
    for (size_t j = 0; j < count;) {
        const uint32_t run_triangle = triangle[j];
        const SurfaceLookup::Corners corners = surface_.corners(run_triangle);
        for (; j < count && triangle[j] == run_triangle; ++j) {
            glm::vec3 position, normal;
            SurfaceLookup::surface_at(corners, bary[j], position, normal);
            for (int c = 0; c < 3; ++c) {
                batch.position[c][j] = position[c];
                batch.normal[c][j] = normal[c];
            }
        }
    }
    orient_points(batch, count, viewer_of(scene.camera));
    thread_local std::vector<float> visibility;
    const bool shadowed = surface_.shadowed();
    if (shadowed) {
        visibility.assign(scene.lights.size() * LightingBatch::kRow, 1.0f);
        for (size_t j = 0; j < count; ++j) {
            const glm::vec3 position(batch.position[0][j], batch.position[1][j], batch.position[2][j]);
            surface_.shadow_visibility(triangle[j], position, visibility.data() + j, LightingBatch::kRow);
        }
    }
    for (size_t first = 0, end; first < count; first = end) {  // runs of one material
        const Material& run_material = surface_.material(triangle[first]);
        for (end = first + 1; end < count && &surface_.material(triangle[end]) == &run_material;) ++end;
        light_points(batch, first, end - first, run_material, scene.lights, scene.settings.ambient_light, specular_,
                     shadowed ? visibility.data() : nullptr);
    }
}

void BlinnPhongShading::shade_many(const uint32_t* triangle, const glm::vec3* bary, size_t count,
                                   glm::vec3* out) const {
    thread_local LightingBatch batch;
    for (size_t start = 0; start < count; start += kLightingBatch) {
        const size_t n = std::min(kLightingBatch, count - start);
        light_batch(triangle + start, bary + start, n, batch);
        auto terms_of = [](size_t j) -> LightingTerms {  // batch is thread_local: no capture
            return {glm::vec3(batch.diffuse[0][j], batch.diffuse[1][j], batch.diffuse[2][j]),
                    glm::vec3(batch.specular[0][j], batch.specular[1][j], batch.specular[2][j])};
        };
        if (surface_.textured()) {
            for (size_t j = 0; j < n; ++j) {
                const uint32_t tri = triangle[start + j];
                glm::vec3 texel(1.0f);
                const bool textured = surface_.texture_factor(tri, bary[start + j], texel);
                out[start + j] = surface_.lit_color(tri, bary[start + j], textured ? &texel : nullptr, terms_of(j));
            }
            continue;
        }
        // Untextured: lit_color's base * diffuse + specular, the base colour looked up once per run of a triangle
        // unless its vertices carry colours.
        for (size_t j = 0; j < n;) {
            const uint32_t run_triangle = triangle[start + j];
            const bool per_vertex = surface_.base_varies(run_triangle);
            const glm::vec3 run_base = surface_.base_color(run_triangle, glm::vec3(1.0f / 3.0f));
            for (; j < n && triangle[start + j] == run_triangle; ++j)
                out[start + j] =
                    lit(per_vertex ? surface_.base_color(run_triangle, bary[start + j]) : run_base, terms_of(j));
        }
    }
}

}  // namespace raster
