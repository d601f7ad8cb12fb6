// An OBJ mesh's materials: its usemtl runs resolved against its mtllib libraries into the mesh's material and
// parts, textures loaded relative to the library that names them.
#pragma once

#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "raster/formats/material_mtl.h"
#include "raster/scene/scene.h"

namespace raster {

// Where the libraries and the images come from (each read once per scene by the loader). Both throw InputError
// naming the file they could not read. `strict` makes a library or image that cannot be read an error.
struct MaterialSources {
    std::function<const std::vector<MtlMaterial>&(const std::filesystem::path&)> library;
    std::function<std::shared_ptr<const Texture>(const std::filesystem::path&)> texture;
    bool strict = false;
};

// The file `name` of a library or image, relative to `folder`: as written, or, when that is missing and the name
// holds backslashes (a Windows exporter's `.\\Texture.jpg`), with them read as separators.
std::filesystem::path file_beside(const std::filesystem::path& folder, const std::string& name);

// Sets mesh.material and mesh.parts from the OBJ's materials; nothing when the OBJ names none. A material's Ka,
// Kd, Ks and Ns replace raster's defaults where given (its colour stays white), unless `coefficients` is given
// (seed 003 scenes set them in the scene): then the OBJ's materials only add their textures to it. map_Kd becomes
// the material's texture (filter trilinear, wrap repeat, or clamp with -clamp on). A usemtl name no library defines
// gets the default material, with a warning, as tinyobjloader did. A material library or image that cannot be read
// is, with sources.strict, an InputError naming the OBJ's mtllib line or the MTL's map_Kd line; otherwise a warning
// there, and the library's materials are missing (their faces get the default material) or the material is drawn
// untextured, as assimp and viewers draw such files.
void apply_obj_materials(SceneMesh& mesh, const std::filesystem::path& obj_path, const MaterialSources& sources,
                         const std::optional<Material>& coefficients);

}  // namespace raster
