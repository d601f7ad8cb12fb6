// OBJ materials: usemtl runs to the mesh's material and parts (obj_materials.h).
#include "raster/formats/obj_materials.h"

#include <algorithm>
#include <cstdio>
#include <system_error>
#include <map>
#include <set>
#include <string>

#include "raster/core/errors.h"
#include "raster/texture/texture.h"

namespace raster {

namespace {

struct FoundMaterial {
    const MtlMaterial* material = nullptr;
    std::filesystem::path library;
};

InputError located(const std::filesystem::path& file, int64_t line, const std::string& what, const InputError& error) {
    return InputError(file.string(), static_cast<int>(std::min<int64_t>(line, INT32_MAX)), 0, what + ": " + error.what());
}

// The problem with a file, as an error (strict) or a warning at the same place (otherwise).
void report(const MaterialSources& sources, const InputError& problem, const char* consequence) {
    if (sources.strict) throw problem;
    std::fprintf(stderr, "%s:%d: warning: %s; %s\n", problem.file().c_str(), problem.line(), problem.message().c_str(),
                 consequence);
}

Material material_for(const FoundMaterial& found, const std::optional<Material>& coefficients,
                      const MaterialSources& sources) {
    Material material = coefficients.value_or(Material{});
    if (!found.material) return material;
    const MtlMaterial& mtl = *found.material;
    material.name = mtl.name;
    if (!coefficients) {
        if (mtl.ambient) material.ambient = *mtl.ambient;
        if (mtl.diffuse) material.diffuse = *mtl.diffuse;
        if (mtl.specular) material.specular = *mtl.specular;
        if (mtl.exponent) material.exponent = *mtl.exponent;
    }
    if (mtl.opacity) material.opacity = *mtl.opacity;  // d / Tr: whatever the scene gives for the coefficients
    if (mtl.diffuse_map) {
        const std::filesystem::path image = file_beside(found.library.parent_path(), mtl.diffuse_map->file);
        TextureBinding binding;
        try {
            binding.texture = sources.texture(image);
            binding.path = binding.texture->path;
            if (mtl.diffuse_map->clamp) binding.wrap = TextureWrap::clamp;
            material.texture = binding;
        } catch (const InputError& error) {
            report(sources, located(found.library, mtl.diffuse_map->line, "map_Kd '" + mtl.diffuse_map->file + "'", error),
                   "the material is drawn untextured");
        }
    }
    return material;
}

}  // namespace

std::filesystem::path file_beside(const std::filesystem::path& folder, const std::string& name) {
    const std::filesystem::path as_written = folder / name;
    if (name.find('\\') == std::string::npos) return as_written;
    std::error_code error;
    if (std::filesystem::exists(as_written, error)) return as_written;
    std::string portable = name;
    std::replace(portable.begin(), portable.end(), '\\', '/');
    return folder / std::filesystem::path(portable).lexically_normal();
}

void apply_obj_materials(SceneMesh& mesh, const std::filesystem::path& obj_path, const MaterialSources& sources,
                         const std::optional<Material>& coefficients) {
    const std::vector<MaterialRun>& runs = mesh.data->material_runs;
    if (runs.empty()) return;
    // The first library to define a name wins.
    std::map<std::string, FoundMaterial> by_name;
    for (const MaterialLibrary& library : mesh.data->material_libraries) {
        const std::filesystem::path path = file_beside(obj_path.parent_path(), library.file);
        const std::vector<MtlMaterial>* materials = nullptr;
        try {
            materials = &sources.library(path);
        } catch (const InputError& error) {
            report(sources, located(obj_path, library.line, "mtllib '" + library.file + "'", error),
                   "its materials are missing, and the faces using them get the default material");
            continue;
        }
        for (const MtlMaterial& material : *materials)
            if (material.named) by_name.try_emplace(material.name, FoundMaterial{&material, path});
    }
    std::set<std::string> warned;
    mesh.parts.clear();
    for (const MaterialRun& run : runs) {
        FoundMaterial found;
        if (const auto it = by_name.find(run.name); it != by_name.end()) {
            found = it->second;
        } else if (!run.name.empty() && warned.insert(run.name).second) {
            std::fprintf(stderr, "%s: warning: usemtl '%s' is not defined by the mesh's material libraries; its faces "
                                 "get the default material\n", obj_path.string().c_str(), run.name.c_str());
        }
        Material material = material_for(found, coefficients, sources);
        if (run.first_triangle == 0) mesh.material = std::move(material);
        else mesh.parts.push_back({run.first_triangle, std::move(material)});
    }
}

}  // namespace raster
