// The raster scene format's reader, and what every scene format's reader shares (the scene's file loaders, the
// camera's nodes to blame, transform chains): the course documents' readers (raster/compat/) use them too.
#pragma once

#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include <glm/mat4x4.hpp>

#include "raster/scene/animation.h"
#include "raster/scene/scene.h"
#include "raster/scene/validation.h"
#include "raster/formats/document_reader.h"

namespace raster {

// Resolves a mesh path from a scene relative to the scene file's folder and loads it (each file once per scene; the
// meshes that name one file share its data).
using MeshFileLoader = std::function<std::shared_ptr<const MeshData>(const Node& where, const std::string& path)>;

// Sets a mesh's material and parts from the materials of the OBJ `file` it was read from (obj_materials.h).
using ObjMaterialLoader = std::function<void(const Node& where, const std::string& file, SceneMesh& mesh,
                                             const std::optional<Material>& coefficients)>;
// Loads a texture a scene names, relative to the scene file's folder (each image once per scene).
using TextureFileLoader = std::function<std::shared_ptr<const Texture>(const Node& where, const std::string& file)>;
struct SceneFileLoaders {
    MeshFileLoader mesh;
    ObjMaterialLoader obj_materials;
    TextureFileLoader texture;
};

// The raster format's `render` section into `settings`.
void read_raster_render(const Node& node, const DocumentReader& reader, RenderSettings& settings);
void read_raster_scene(const Node& root, const DocumentReader& reader, const SceneFileLoaders& files, Scene& scene);
// One entry of the raster format's `meshes` (or `shapes`): a file or an inline mesh, its transform and material.
SceneMesh read_raster_mesh(const Node& node, const DocumentReader& reader, const SceneFileLoaders& files);
// A scene-graph node's `keyframes` (and `interpolation`) into `animated`'s tracks (docs/animation.md).
void read_raster_keyframes(const Node& node, const DocumentReader& reader, AnimatedNode& animated);
// The raster format's scene graph (`shapes` and `nodes`), each placement appended to the scene's meshes; an
// animation when a node has keyframes, the scene posed at time 0.
void read_raster_graph(const Node& root, const DocumentReader& reader, const SceneFileLoaders& files, Scene& scene);

// A camera's nodes in a document (undefined where the file leaves the value to its default), and the node to blame
// for a camera problem: the value's own node, else the node it is relative to (target and up: the eye; far: near),
// else the camera's map.
struct CameraNodes {
    const Node &map, &eye, &target, &up, &fov, &near, &far, &height;
};
const Node& camera_node_to_blame(const CameraNodes& nodes, CameraField field);

// A transform chain: a list of single-key maps (translate, rotate, quaternion, scale, lookat), applied to the
// object in the order listed (the matrix is M = T_n * ... * T_1), read into steps as written; and the same for steps
// gathered otherwise.
std::vector<TransformStep> read_transform_chain(const Node& list, const DocumentReader& reader);
// One step's value as `kind` (translate, rotate, quaternion, scale or lookat) reads it.
TransformStep read_transform_step(const std::string& kind, const Node& value, const DocumentReader& reader);
std::vector<TransformStep> read_transform_steps(const std::vector<std::reference_wrapper<const Node>>& steps,
                                                const DocumentReader& reader);

}  // namespace raster
