// Prelit lighting: Blinn-Phong terms per face or vertex, shadowed lights apart, and their combination per sample.
#include "raster/shading/prelit_lighting.h"

#include "raster/shading/viewer.h"

namespace raster {

PrelitLighting::PrelitLighting(const SurfaceLookup& surface) : surface_(surface) {
    if (surface.shadowed()) stride_ = 1 + surface.shadowed_lights().size();
}

void PrelitLighting::light(const glm::vec3& position, const glm::vec3& normal, const Material& material,
                           LightingTerms* out) const {
    const Scene& scene = surface_.scene();
    const glm::vec3 to_eye = to_viewer(viewer_of(scene.camera), position);
    if (stride_ == 1) {
        out[0] = evaluate_lighting(position, normal, to_eye, material, scene.lights, scene.settings.ambient_light,
                                   SpecularModel::blinn, nullptr);
        return;
    }
    out[0] = evaluate_lighting(position, normal, to_eye, material, surface_.unshadowed_lights(),
                               scene.settings.ambient_light, SpecularModel::blinn, nullptr);
    const std::vector<size_t>& shadowed = surface_.shadowed_lights();
    for (size_t k = 0; k < shadowed.size(); ++k)
        out[1 + k] = evaluate_lighting(position, normal, to_eye, material, {scene.lights[shadowed[k]]},
                                       glm::vec3(0.0f), SpecularModel::blinn, nullptr);
}

LightingTerms PrelitLighting::combined(const LightingTerms* terms, const float* visibility) const {
    LightingTerms out = terms[0];
    if (!visibility) return out;
    const std::vector<size_t>& shadowed = surface_.shadowed_lights();
    for (size_t k = 0; k < shadowed.size(); ++k) {
        const float visible = visibility[shadowed[k]];
        out.diffuse += terms[1 + k].diffuse * visible;
        out.specular += terms[1 + k].specular * visible;
    }
    return out;
}

}  // namespace raster
