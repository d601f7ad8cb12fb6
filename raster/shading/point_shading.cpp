// Unlit, cel and Gooch shading, point by point.
#include "raster/shading/point_shading.h"

#include "raster/shading/stylized_lighting.h"
#include "raster/shading/viewer.h"

namespace raster {

void UnlitShading::shade_many(const uint32_t* triangle, const glm::vec3* bary, size_t count, glm::vec3* out) const {
    for (size_t j = 0; j < count; ++j) {
        glm::vec3 texel(1.0f);
        const bool textured = surface_.texture_factor(triangle[j], bary[j], texel);
        const glm::vec3 base = surface_.base_color(triangle[j], bary[j]);
        out[j] = textured ? base * texel : base;
    }
}

StylizedShading::StylizedShading(const SurfaceLookup& surface, ShadingMode mode)
    : surface_(surface), cel_(mode == ShadingMode::cel) {}

LightingTerms StylizedShading::light_at(uint32_t triangle, const glm::vec3& bary, const float* visibility) const {
    glm::vec3 position, normal;
    SurfaceLookup::surface_at(surface_.corners(triangle), bary, position, normal);
    const Scene& scene = surface_.scene();
    const glm::vec3 unit_normal = unit_or_zero(normal), to_eye = to_viewer(viewer_of(scene.camera), position);
    const RenderSettings& settings = scene.settings;
    if (cel_)
        return evaluate_cel_lighting(position, unit_normal, to_eye, surface_.material(triangle), scene.lights,
                                     settings.ambient_light, settings.cel_bands, visibility);
    return evaluate_gooch_lighting(position, unit_normal, to_eye, surface_.material(triangle), scene.lights,
                                   settings.gooch, visibility);
}

void StylizedShading::shade_many(const uint32_t* triangle, const glm::vec3* bary, size_t count,
                                 glm::vec3* out) const {
    for (size_t j = 0; j < count; ++j) {
        glm::vec3 texel(1.0f);
        const bool textured = surface_.texture_factor(triangle[j], bary[j], texel);
        const float* visibility = surface_.visibility_at(triangle[j], bary[j]);
        out[j] = surface_.lit_color(triangle[j], bary[j], textured ? &texel : nullptr,
                                    light_at(triangle[j], bary[j], visibility));
    }
}

}  // namespace raster
