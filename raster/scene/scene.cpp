// Names of the scene's enumerations, shared by the loaders and the command line, and a look-at step's camera.
#include "raster/scene/scene.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <utility>

namespace raster {

namespace {
struct ShadingName {
    ShadingMode mode;
    const char* name;
};
constexpr ShadingName kShadingNames[] = {
    {ShadingMode::unlit, "unlit"},     {ShadingMode::flat, "flat"},
    {ShadingMode::gouraud, "gouraud"}, {ShadingMode::phong, "phong"},
    {ShadingMode::blinn_phong, "blinn-phong"}, {ShadingMode::cel, "cel"},
    {ShadingMode::gooch, "gooch"},
};
}  // namespace

const char* to_string(ShadingMode mode) {
    for (const auto& entry : kShadingNames)
        if (entry.mode == mode) return entry.name;
    return "?";
}

std::shared_ptr<const MeshData> shared_mesh_data(MeshData data) { return std::make_shared<MeshData>(std::move(data)); }

MeshData& mutable_data(SceneMesh& mesh) {
    if (mesh.data.use_count() != 1) mesh.data = shared_mesh_data(*mesh.data);
    // Every SceneMesh's data is made by shared_mesh_data as a (non-const) MeshData, so this const_cast is defined.
    return const_cast<MeshData&>(*mesh.data);
}

SpotFade spot_fade(const Light& light) {
    const double inner = std::cos(static_cast<double>(light.inner_cone));
    const double outer = std::cos(static_cast<double>(light.outer_cone));
    const double scale = 1.0 / std::max(0.001, inner - outer);
    return {static_cast<float>(scale), static_cast<float>(-outer * scale)};
}

Camera look_at_camera(const LookAtStep& step) {
    Camera camera;
    camera.eye = step.eye;
    camera.target = step.target;
    camera.up = step.up;
    return camera;
}

const char* to_string(SamplePattern pattern) { return pattern == SamplePattern::grid ? "grid" : "standard"; }

bool parse_shading_mode(const std::string& name, ShadingMode& out) {
    for (const auto& entry : kShadingNames) {
        if (name == entry.name) {
            out = entry.mode;
            return true;
        }
    }
    return false;
}

bool parse_sample_pattern(const std::string& name, SamplePattern& out) {
    if (name == "standard") out = SamplePattern::standard;
    else if (name == "grid") out = SamplePattern::grid;
    else return false;
    return true;
}

const Material& material_of(const SceneMesh& mesh, uint32_t triangle) {
    const auto after = std::upper_bound(mesh.parts.begin(), mesh.parts.end(), triangle,
                                        [](uint32_t t, const MaterialPart& part) { return t < part.first_triangle; });
    return after == mesh.parts.begin() ? mesh.material : std::prev(after)->material;
}

namespace {

// Whether some material of some mesh satisfies `test`.
template <typename Test>
bool any_material(const Scene& scene, Test test) {
    bool found = false;
    for (const SceneMesh& mesh : scene.meshes)
        for_each_material(mesh, [&](const Material& material) { found = found || test(material); });
    return found;
}

}  // namespace

bool has_textures(const Scene& scene) {
    return any_material(scene, [](const Material& material) { return material.texture.has_value(); });
}

bool has_shadows(const Scene& scene) {
    return std::any_of(scene.lights.begin(), scene.lights.end(), [](const Light& light) { return light.shadows; });
}

bool has_transparency(const Scene& scene) {
    return any_material(scene, [](const Material& material) { return is_blended(material); });
}

void set_shadow_casting(Scene& scene, bool on) {
    for (Light& light : scene.lights) light.shadows = on && light.type != LightType::directional;
}

bool can_cast_shadows(const Scene& scene) {
    return std::any_of(scene.lights.begin(), scene.lights.end(),
                       [](const Light& light) { return light.type != LightType::directional; });
}

void draw_every_material_opaque(Scene& scene) {
    for (SceneMesh& mesh : scene.meshes)
        for_each_material(mesh, [](Material& material) {
            material.opacity = 1.0f;
            if (material.texture) material.texture->reads_alpha = false;
        });
}

const char* to_string(TransparencyMode mode) { return mode == TransparencyMode::sorted ? "sorted" : "weighted"; }

bool parse_transparency_mode(const std::string& name, TransparencyMode& out) {
    if (name == "sorted") out = TransparencyMode::sorted;
    else if (name == "weighted") out = TransparencyMode::weighted;
    else return false;
    return true;
}

size_t triangle_count(const Scene& scene) {
    size_t total = 0;
    for (const auto& mesh : scene.meshes) total += mesh.data->triangles.size();
    return total;
}

bool valid_resolution_divisor(int divisor) { return divisor == 1 || divisor == 2 || divisor == 4; }

RenderSettings internal_frame_settings(RenderSettings settings) {
    settings.width /= settings.resolution_divisor;
    settings.height /= settings.resolution_divisor;
    settings.resolution_divisor = 1;
    return settings;
}

}  // namespace raster
