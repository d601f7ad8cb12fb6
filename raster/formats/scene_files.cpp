// A scene's files, each read once (scene_files.h).
#include "raster/formats/scene_files.h"

#include <cstdio>
#include <map>
#include <memory>

#include "raster/core/errors.h"
#include "raster/core/file_io.h"
#include "raster/formats/obj_materials.h"
#include "raster/formats/mesh_file.h"
#include "raster/texture/mip_chains.h"
#include "raster/texture/texture.h"

namespace raster {

SceneFiles::SceneFiles(const std::filesystem::path& scene_path, const DocumentReader& reader, bool strict)
    : folder_(scene_path.parent_path()), reader_(reader), strict_(strict) {}

std::filesystem::path SceneFiles::resolve(const std::string& file) const {
    std::filesystem::path path(file);
    if (path.is_relative()) path = folder_ / path;
    return path.lexically_normal();
}

std::shared_ptr<const MeshData> SceneFiles::mesh(const Node& where, const std::string& file) {
    const std::filesystem::path path = resolve(file);
    auto& slot = meshes_[path.string()];
    if (!slot) {
        try {
            slot = shared_mesh_data(load_mesh_file(path));
        } catch (const InputError& error) {
            // Say where the scene asked for the mesh, and what is wrong inside it.
            reader_.fail(where, "in mesh '" + file + "': " + error.what());
        }
    }
    return slot;
}

const std::vector<MtlMaterial>& SceneFiles::library(const std::filesystem::path& path) {
    const std::string key = path.lexically_normal().string();
    if (const auto it = libraries_.find(key); it != libraries_.end()) return it->second;
    std::vector<MtlMaterial> materials = parse_mtl(read_file_bytes(path, uint64_t{1} << 28), key, strict_);
    return libraries_.emplace(key, std::move(materials)).first->second;
}

std::shared_ptr<const Texture> SceneFiles::texture(const std::filesystem::path& path) {
    auto& slot = textures_[path.lexically_normal().string()];
    if (!slot) slot = std::make_shared<const Texture>(load_texture(path.lexically_normal()));
    return slot;
}

SceneFileLoaders SceneFiles::loaders() {
    SceneFileLoaders files;
    files.mesh = [this](const Node& where, const std::string& file) { return mesh(where, file); };
    files.obj_materials = [this](const Node& where, const std::string& file, SceneMesh& target,
                                 const std::optional<Material>& coefficients) {
        MaterialSources sources;
        sources.library = [this](const std::filesystem::path& path) -> const std::vector<MtlMaterial>& {
            return library(path);
        };
        sources.texture = [this](const std::filesystem::path& path) { return texture(path); };
        sources.strict = strict_;
        try {
            apply_obj_materials(target, resolve(file), sources, coefficients);
        } catch (const InputError& error) {
            reader_.fail(where, "in mesh '" + file + "': " + error.what());
        }
    };
    files.texture = [this](const Node& where, const std::string& file) {
        try {
            return texture(resolve(file));
        } catch (const InputError& error) {
            reader_.fail(where, error.what());
        }
    };
    return files;
}

namespace {

// Whether any material of the mesh is textured.
bool reads_texture(const SceneMesh& mesh) {
    bool textured = false;
    for_each_material(mesh, [&](const Material& m) { textured = textured || m.texture.has_value(); });
    return textured;
}

}  // namespace

void finish_scene_textures(Scene& scene) {
    // Texture coordinates that no placement of a mesh's data reads are dropped, once for all its placements.
    std::map<const MeshData*, bool> read;
    for (const SceneMesh& mesh : scene.meshes) read[mesh.data.get()] = read[mesh.data.get()] || reads_texture(mesh);
    std::map<const MeshData*, std::shared_ptr<const MeshData>> without_uvs;
    for (SceneMesh& mesh : scene.meshes) {
        const MeshData* data = mesh.data.get();
        if (read[data] || data->corner_uvs.empty()) continue;
        std::shared_ptr<const MeshData>& replacement = without_uvs[data];
        if (!replacement) {
            MeshData copy = *data;
            copy.corner_uvs = {};
            replacement = shared_mesh_data(std::move(copy));
        }
        mesh.data = replacement;
    }
    for (SceneMesh& mesh : scene.meshes) {
        if (reads_texture(mesh) && mesh.data->corner_uvs.empty()) {
            std::fprintf(stderr, "%s: warning: mesh '%s' has a textured material but no texture coordinates on every "
                                 "corner; it is drawn untextured\n", scene.path.c_str(), mesh.source.c_str());
            for_each_material(mesh, [](Material& m) { m.texture.reset(); });
        }
    }
    build_needed_mip_chains(scene);
}

}  // namespace raster
