// Loading scenes: one entry point for every scene file raster reads, its own YAML or a course document's, told apart
// by content; and what such a file asks of `raster render` besides its scene (a seed 000 config names its output and
// its task), so that the renderer and the command line know scenes and outputs, not homeworks.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "raster/scene/scene.h"

namespace raster {

enum class SceneFormat {
    raster,   // the project's own YAML format (docs/scene-format.md)
    seed003,  // the seed 003 course's JSON scene (eye / lookat / fov_angle / meshes[].obj)
    seed000,  // the seed 000 course's YAML config (task / resolution / obj / camera / transforms / lights)
    seed001,  // the seed 001 course's balboa JSON scene (camera / background / objects)
    mesh,     // a mesh file alone (.obj or .ply), framed by a default camera and light (mesh_scene.h)
    gltf,     // a glTF 2.0 file (.gltf or .glb): its default scene (raster/gltf/gltf_scene.h, docs/gltf.md)
};

// Which format a scene file is: a mesh or a glTF file by its extension (.obj, .ply; .gltf, .glb); else, parsed as a document, by its top-level
// keys: seed 000 with `task`; seed 001 with `camera` and `objects`; seed 003 with `fov_angle` or `lookat`; else
// raster.
const char* to_string(SceneFormat format);

// What a scene file asks of `raster render` besides drawing its scene.
struct FileRequest {
    std::filesystem::path output;  // the file's own name for the image it asks for; empty: none
    bool depth_image = false;      // that image is the depth image, not the colour image (seed 000 shading-depth)
    // A check the file asks for instead of a render (seed 000's transform-test): prints its result and returns
    // whether it passed. Empty when the file asks for a render.
    std::function<bool(std::ostream& out)> self_check;
};

struct SceneFile {
    Scene scene;
    SceneFormat format = SceneFormat::raster;
    FileRequest request;
    // glTF: every camera node's name, in the order SceneLoadOptions::camera counts them; empty for other formats.
    std::vector<std::string> cameras;
};

// How leniently the files a scene names are read.
struct SceneLoadOptions {
    // An OBJ's material library or image that cannot be read, or its MTL's nameless newmtl, is an error; without
    // it, a warning, and the model is drawn with default materials or untextured (docs/scene-format.md#meshes).
    bool strict = false;
    // glTF: the camera node to draw from, in the order the default scene's trees are walked (0 the first; docs/gltf.md).
    // Another format has one camera: anything but 0 is an error.
    int camera = 0;
};

// Loads, validates (validate_scene) and returns a scene file, parsed once. Relative mesh paths are relative to the
// scene file. Throws InputError naming the file, line and column of the problem.
SceneFile load_scene_file(const std::filesystem::path& path, const SceneLoadOptions& options = {});
// The same from text already in memory; `path` names it in messages and anchors relative mesh paths.
SceneFile parse_scene_file(std::string_view text, const std::filesystem::path& path, const SceneLoadOptions& options = {});

// The scene alone: load_scene_file's, its format into `format` when given.
Scene load_scene(const std::filesystem::path& path, SceneFormat* format = nullptr);
Scene parse_scene(std::string_view text, const std::filesystem::path& path, SceneFormat* format = nullptr);

}  // namespace raster
