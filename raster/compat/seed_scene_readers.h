// The course documents' scene readers, each filling a Scene from a parsed document (internal to the scene loader);
// seed 000's are in scene_format_seed000.h with the rest of its config.
#pragma once

#include "raster/compat/scene_format_seed000.h"
#include "raster/formats/document_reader.h"
#include "raster/formats/scene_formats.h"
#include "raster/scene/scene.h"

namespace raster {

// Seed 003 JSON scenes: eye / lookat / up / fov_angle, lights, meshes[].obj.
void read_seed003_scene(const Node& root, const DocumentReader& reader, const SceneFileLoaders& files, Scene& scene);
// Seed 001 (balboa) JSON scenes: camera with resolution / transform / s / z_near, background, objects.
void read_seed001_scene(const Node& root, const DocumentReader& reader, const MeshFileLoader& load_mesh, Scene& scene);

}  // namespace raster
