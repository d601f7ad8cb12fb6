// Shading: the model of the scene's mode, chosen once per frame.
#include "raster/shading/shade.h"

#include "raster/shading/blinn_phong_shading.h"
#include "raster/shading/flat_shading.h"
#include "raster/shading/gouraud_shading.h"
#include "raster/shading/point_shading.h"

namespace raster {
namespace {

std::unique_ptr<ShadingModel> model_for(ShadingMode mode, const SurfaceLookup& surface) {
    switch (mode) {
        case ShadingMode::unlit: return std::make_unique<UnlitShading>(surface);
        case ShadingMode::flat: return std::make_unique<FlatShading>(surface);
        case ShadingMode::gouraud: return std::make_unique<GouraudShading>(surface);
        case ShadingMode::phong: return std::make_unique<BlinnPhongShading>(surface, SpecularModel::phong);
        case ShadingMode::blinn_phong: return std::make_unique<BlinnPhongShading>(surface, SpecularModel::blinn);
        case ShadingMode::cel:
        case ShadingMode::gooch: return std::make_unique<StylizedShading>(surface, mode);
    }
    return std::make_unique<UnlitShading>(surface);
}

}  // namespace

Shader::Shader(const Scene& scene, const TransformedScene& geometry, const ShadowMaps* shadows)
    : surface_(scene, geometry, shadows), model_(model_for(scene.settings.shading, surface_)) {}

glm::vec3 Shader::shade(uint32_t triangle, const glm::vec3& bary) const {
    glm::vec3 color;
    shade_many(&triangle, &bary, 1, &color);
    return color;
}

}  // namespace raster
