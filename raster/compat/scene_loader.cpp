// Loading scenes: reads the file, tells the format apart by content, loads each mesh file once, validates, and
// says what the file asks for besides its scene.
#include "raster/compat/scene_loader.h"

#include <utility>

#include "raster/core/errors.h"
#include "raster/core/file_io.h"
#include "raster/compat/mesh_scene.h"
#include "raster/compat/seed_scene_readers.h"
#include "raster/formats/document.h"
#include "raster/formats/document_reader.h"
#include "raster/formats/mesh_file.h"
#include "raster/gltf/gltf_scene.h"
#include "raster/formats/scene_files.h"
#include "raster/scene/validation.h"

namespace raster {

const char* to_string(SceneFormat format) {
    switch (format) {
        case SceneFormat::raster: return "raster";
        case SceneFormat::seed003: return "seed003";
        case SceneFormat::seed000: return "seed000";
        case SceneFormat::seed001: return "seed001";
        case SceneFormat::mesh: return "mesh";
        case SceneFormat::gltf: return "gltf";
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

// The request of a seed 000 config: its output, and its task's image or self-check.
FileRequest seed000_request(const Seed000Config& config) {
    FileRequest request;
    if (config.task == Seed000Task::transform_test) {
        request.self_check = [config](std::ostream& out) {
            const Seed000TestResult test = run_seed000_transform_test(config);
            out << format_seed000_test_result(test);
            return test.match;
        };
        return request;
    }
    request.output = config.output;
    request.depth_image = config.task == Seed000Task::shading_depth;
    return request;
}

// A mesh file's scene, from its loaded mesh.
SceneFile mesh_scene_file(MeshData data, const std::filesystem::path& path, const SceneLoadOptions& options) {
    const DocumentReader reader(path.string());
    SceneFiles files(path, reader, options.strict);
    SceneFile out;
    out.format = SceneFormat::mesh;
    read_mesh_file_scene(std::move(data), path, files.loaders(), out.scene);
    finish_scene_textures(out.scene);
    validate_scene(out.scene);
    return out;
}

// Any camera but the first asked of a file that has one camera (every format but glTF) is an error.
void refuse_camera_choice(const std::filesystem::path& path, const SceneLoadOptions& options) {
    if (options.camera != 0 && !is_gltf_file(path))
        throw InputError(path.string(), 0, 0, "camera " + std::to_string(options.camera) +
                                                  " asked for: only a glTF file places cameras to choose from");
}

// A glTF file's scene: framed and lit by default where the file has no camera or no point light.
SceneFile gltf_scene_file(std::string_view bytes, const std::filesystem::path& path, int camera) {
    SceneFile out;
    out.format = SceneFormat::gltf;
    const GltfSceneParts parts = read_gltf_scene(bytes, path.string(), gltf_folder_reader(path), out.scene, camera);
    out.cameras = parts.cameras;
    frame_scene(out.scene, !parts.camera, !parts.lights);
    finish_scene_textures(out.scene);
    validate_scene(out.scene);
    return out;
}

}  // namespace

SceneFile parse_scene_file(std::string_view text, const std::filesystem::path& path, const SceneLoadOptions& options) {
    refuse_camera_choice(path, options);
    if (is_gltf_file(path)) return gltf_scene_file(text, path, options.camera);
    if (is_mesh_file(path)) return mesh_scene_file(parse_mesh_file(text, path), path, options);
    const std::string name = path.string();
    const Document document = parse_document(text, name);
    const Node& root = document.root();
    const DocumentReader reader(name);
    if (!root.is_defined() || root.is_null()) throw InputError(name, 1, 1, "the scene file is empty");
    reader.expect_map(root, "a scene");

    SceneFiles files(path, reader, options.strict);
    const SceneFileLoaders loaders = files.loaders();
    SceneFile out;
    Scene& scene = out.scene;
    scene.path = name;
    out.format = detect_format(root, reader);
    switch (out.format) {
        case SceneFormat::raster: read_raster_scene(root, reader, loaders, scene); break;
        case SceneFormat::seed003: read_seed003_scene(root, reader, loaders, scene); break;
        case SceneFormat::seed000: {
            const Seed000Config config = read_seed000_config(root, reader);
            read_seed000_scene(root, reader, config, loaders.mesh, scene);
            out.request = seed000_request(config);
            break;
        }
        case SceneFormat::seed001: read_seed001_scene(root, reader, loaders.mesh, scene); break;
        case SceneFormat::mesh:
        case SceneFormat::gltf: break;  // told by the extension before any parse; detect_format never says them
    }
    finish_scene_textures(scene);
    validate_scene(scene);
    return out;
}

SceneFile load_scene_file(const std::filesystem::path& path, const SceneLoadOptions& options) {
    refuse_camera_choice(path, options);
    if (is_mesh_file(path)) return mesh_scene_file(load_mesh_file(path), path, options);  // the mesh readers' own caps
    if (is_gltf_file(path)) return gltf_scene_file(read_file_bytes(path, kMaxGltfFileBytes), path, options.camera);
    return parse_scene_file(read_file_bytes(path, kMaxSceneFileBytes), path, options);
}

Scene parse_scene(std::string_view text, const std::filesystem::path& path, SceneFormat* format) {
    SceneFile file = parse_scene_file(text, path);
    if (format) *format = file.format;
    return std::move(file.scene);
}

Scene load_scene(const std::filesystem::path& path, SceneFormat* format) {
    SceneFile file = load_scene_file(path);
    if (format) *format = file.format;
    return std::move(file.scene);
}

}  // namespace raster
