// Loading scenes: one entry point for every scene format raster reads, told apart by content.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "raster/scene/scene.h"

namespace raster {

enum class SceneFormat {
    raster,   // the project's own YAML format (README "Scene format")
    seed003,  // the seed 003 course's JSON scene (eye / lookat / fov_angle / meshes[].obj)
    seed000,  // the seed 000 course's YAML config (task / resolution / obj / camera / transforms / lights)
    seed001,  // the seed 001 course's balboa JSON scene (camera / background / objects)
};

// Which format a parsed document is, by its top-level keys: seed 000 with `task`; seed 001 with `camera` and
// `objects`; seed 003 with `fov_angle` or `lookat`; else raster.
const char* to_string(SceneFormat format);

// Loads, validates (validate_scene) and returns a scene. Relative mesh paths are relative to the scene file.
// Throws InputError naming the file, line and column of the problem. `format`, when given, receives the format.
Scene load_scene(const std::filesystem::path& path, SceneFormat* format = nullptr);

// The same from text already in memory; `path` names it in messages and anchors relative mesh paths.
Scene parse_scene(std::string_view text, const std::filesystem::path& path, SceneFormat* format = nullptr);

// Loads a mesh file by extension: .obj (Wavefront) or .ply (Stanford). Throws InputError.
MeshData load_mesh_file(const std::filesystem::path& path);

// Largest scene file read, in bytes.
inline constexpr uint64_t kMaxSceneFileBytes = uint64_t{256} << 20;

}  // namespace raster
