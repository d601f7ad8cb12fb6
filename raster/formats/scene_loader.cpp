// Loading scenes: reads the file, tells the format apart by content, loads each mesh file once, validates.
#include "raster/formats/scene_loader.h"

#include <algorithm>
#include <map>
#include <memory>

#include "raster/core/errors.h"
#include "raster/core/file_io.h"
#include "raster/formats/mesh_obj.h"
#include "raster/formats/mesh_ply.h"
#include "raster/scene/validation.h"
#include "raster/formats/scene_formats.h"
#include "raster/formats/document_reader.h"
#include "raster/formats/scene_files.h"

namespace raster {

const char* to_string(SceneFormat format) {
    switch (format) {
        case SceneFormat::raster: return "raster";
        case SceneFormat::seed003: return "seed003";
        case SceneFormat::seed000: return "seed000";
        case SceneFormat::seed001: return "seed001";
    }
    return "?";
}

namespace {

SceneFormat detect_format(const Node& root, const DocumentReader& reader) {
    auto has = [&](const char* key) { return reader.optional(root, key).is_defined(); };
    if (has("task")) return SceneFormat::seed000;
    if (has("camera") && has("objects")) return SceneFormat::seed001;
    if (has("fov_angle") || has("lookat")) return SceneFormat::seed003;
    return SceneFormat::raster;
}

}  // namespace

MeshData load_mesh_file(const std::filesystem::path& path) {
    std::string extension = path.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return std::tolower(c); });
    if (extension == ".obj") return load_obj(path);
    if (extension == ".ply") return load_ply(path);
    throw InputError(path.string(), 0, 0, "unknown mesh format '" + extension + "' (expected .obj or .ply)");
}

Scene parse_scene(std::string_view text, const std::filesystem::path& path, SceneFormat* format) {
    const std::string name = path.string();
    const Document document = parse_document(text, name);
    const Node& root = document.root();
    const DocumentReader reader(name);
    if (!root.is_defined() || root.is_null()) throw InputError(name, 1, 1, "the scene file is empty");
    reader.expect_map(root, "a scene");

    SceneFiles files(path, reader);
    const SceneFileLoaders loaders = files.loaders();
    Scene scene;
    scene.path = name;
    const SceneFormat detected = detect_format(root, reader);
    switch (detected) {
        case SceneFormat::raster: read_raster_scene(root, reader, loaders, scene); break;
        case SceneFormat::seed003: read_seed003_scene(root, reader, loaders, scene); break;
        case SceneFormat::seed000: read_seed000_scene(root, reader, loaders.mesh, scene); break;
        case SceneFormat::seed001: read_seed001_scene(root, reader, loaders.mesh, scene); break;
    }
    finish_scene_textures(scene);
    validate_scene(scene);
    if (format) *format = detected;
    return scene;
}

Scene load_scene(const std::filesystem::path& path, SceneFormat* format) {
    return parse_scene(read_file_bytes(path, kMaxSceneFileBytes), path, format);
}

}  // namespace raster
