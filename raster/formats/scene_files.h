// The files a scene refers to (meshes, material libraries, textures), each read once, resolved relative to the
// file that names them, and handed to the format readers as SceneFileLoaders.
#pragma once

#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "raster/formats/document_reader.h"
#include "raster/formats/material_mtl.h"
#include "raster/formats/scene_formats.h"

namespace raster {

class SceneFiles {
public:
    // `scene_path` is the scene file (relative names resolve against its folder); `reader` locates errors in it.
    // Both must outlive the loaders.
    // `strict`: an OBJ's material library or image that cannot be read, or an MTL's nameless newmtl, is an error
    // rather than a warning (obj_materials.h).
    SceneFiles(const std::filesystem::path& scene_path, const DocumentReader& reader, bool strict = false);

    SceneFileLoaders loaders();

private:
    std::filesystem::path resolve(const std::string& file) const;
    std::shared_ptr<const MeshData> mesh(const Node& where, const std::string& file);
    const std::vector<MtlMaterial>& library(const std::filesystem::path& path);
    std::shared_ptr<const Texture> texture(const std::filesystem::path& path);

    std::filesystem::path folder_;
    const DocumentReader& reader_;
    bool strict_;
    std::map<std::string, std::shared_ptr<const MeshData>> meshes_;
    std::map<std::string, std::vector<MtlMaterial>> libraries_;
    std::map<std::string, std::shared_ptr<const Texture>> textures_;
};

// What the scene's materials need once every mesh is read: texture coordinates dropped from meshes no textured
// material reads (a warning, and the texture dropped, where a textured material's mesh has none), and the mip
// chain built for every texture whose filter reads one.
void finish_scene_textures(Scene& scene);

}  // namespace raster
