// glTF 2.0 scenes (.gltf and .glb) read into raster's Scene (docs/gltf.md): the default scene's node trees, each
// mesh placed by its node's transform chain as written, its camera and point lights.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "raster/gltf/gltf_model.h"
#include "raster/scene/scene.h"

namespace raster {

// Whether `path` names a glTF file: its extension is .gltf or .glb, in any case.
bool is_gltf_file(const std::filesystem::path& path);

// What the file gave besides meshes: the caller frames a scene without a camera and lights one without lights, as
// it does a mesh file alone.
struct GltfSceneParts {
    bool camera = false;
    bool lights = false;
    // Every camera node's name ("camera N" for a nameless one), in the order `camera` counts them.
    std::vector<std::string> cameras;
};

// The most nodes deep a tree may be, and the most triangles its meshes may hold and its nodes place together (each
// placement holds its own copy).
inline constexpr int kMaxGltfNodeDepth = 256;
inline constexpr uint64_t kMaxGltfPlacedTriangles = kMaxMeshTriangles;
// The most primitives the nodes may place, and transform steps their chains may hold, together.
inline constexpr uint64_t kMaxGltfPlacements = uint64_t{1} << 16;
inline constexpr uint64_t kMaxGltfPlacedSteps = uint64_t{1} << 22;

// Reads the model `bytes` (its path `name`, its external files through `files`) into `scene`'s meshes, camera and
// lights. The camera is the one of camera node `camera`, counted in the order the default scene's trees are walked
// (depth first, children in order; 0 the first). Throws InputError naming the file and the JSON path of the
// problem, or the cameras there are when `camera` is not one of them.
GltfSceneParts read_gltf_scene(std::string_view bytes, const std::string& name, const GltfFileReader& files, Scene& scene,
                               int camera = 0);

}  // namespace raster
