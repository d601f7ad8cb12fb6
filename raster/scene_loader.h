// Loading scenes: one entry point for every scene format raster reads, told apart by content.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "raster/scene.h"

namespace raster {

enum class SceneFormat {
    raster,   // the project's own YAML format (README "Scene format")
    seed003,  // the seed 003 course's JSON scene (eye / lookat / fov_angle / meshes[].obj)
};

// Which format a parsed document is: seed 003 when it has top-level `fov_angle` or `lookat`, else raster.
const char* to_string(SceneFormat format);

// Loads, validates (validate_scene) and returns a scene. Relative mesh paths are relative to the scene file.
// Throws InputError naming the file, line and column of the problem.
Scene load_scene(const std::filesystem::path& path);

// The same from text already in memory; `path` names it in messages and anchors relative mesh paths.
Scene parse_scene(std::string_view text, const std::filesystem::path& path);

// Loads a mesh file by extension: .obj (Wavefront) or .ply (Stanford). Throws InputError.
MeshData load_mesh_file(const std::filesystem::path& path);

// Largest scene file read, in bytes.
inline constexpr uint64_t kMaxSceneFileBytes = uint64_t{256} << 20;

}  // namespace raster
