// Loading scenes: reads the file, tells the format apart by content, loads each mesh file once, validates.
#include "raster/scene_loader.h"

#include <algorithm>
#include <map>
#include <memory>

#include "raster/errors.h"
#include "raster/file_io.h"
#include "raster/mesh_obj.h"
#include "raster/mesh_ply.h"
#include "raster/render.h"
#include "raster/scene_formats.h"
#include "raster/yaml_reader.h"

namespace raster {

const char* to_string(SceneFormat format) { return format == SceneFormat::seed003 ? "seed003" : "raster"; }

MeshData load_mesh_file(const std::filesystem::path& path) {
    std::string extension = path.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return std::tolower(c); });
    if (extension == ".obj") return load_obj(path);
    if (extension == ".ply") return load_ply(path);
    throw InputError(path.string(), 0, 0, "unknown mesh format '" + extension + "' (expected .obj or .ply)");
}

Scene parse_scene(std::string_view text, const std::filesystem::path& path) {
    const std::string name = path.string();
    const YAML::Node root = parse_document(text, name);
    const YamlReader reader(name);
    if (!root.IsDefined() || root.IsNull()) throw InputError(name, 1, 1, "the scene file is empty");
    reader.expect_map(root, "a scene");

    std::map<std::string, std::unique_ptr<MeshData>> meshes;
    const MeshFileLoader load_mesh = [&](const YAML::Node& where, const std::string& file) -> const MeshData& {
        std::filesystem::path mesh_path(file);
        if (mesh_path.is_relative()) mesh_path = path.parent_path() / mesh_path;
        auto& slot = meshes[mesh_path.lexically_normal().string()];
        if (!slot) {
            try {
                slot = std::make_unique<MeshData>(load_mesh_file(mesh_path));
            } catch (const InputError& error) {
                // Say where the scene asked for the mesh, and what is wrong inside it.
                reader.fail(where, "in mesh '" + file + "': " + error.what());
            }
        }
        return *slot;
    };

    Scene scene;
    scene.path = name;
    const bool seed003 = reader.optional(root, "fov_angle").IsDefined() || reader.optional(root, "lookat").IsDefined();
    if (seed003) read_seed003_scene(root, reader, load_mesh, scene);
    else read_raster_scene(root, reader, load_mesh, scene);
    validate_scene(scene);
    return scene;
}

Scene load_scene(const std::filesystem::path& path) {
    return parse_scene(read_file_bytes(path, kMaxSceneFileBytes), path);
}

}  // namespace raster
