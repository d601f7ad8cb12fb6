// A mesh file alone as a scene: an OBJ or PLY file given where a scene is expected renders as itself, framed by a
// default camera and lit by a default light (docs/scene-format.md#a-mesh-file-alone); a glTF file without a camera
// or lights is framed and lit the same way.
#pragma once

#include <filesystem>

#include <glm/vec3.hpp>

#include "raster/formats/scene_formats.h"
#include "raster/scene/scene.h"

namespace raster {

// The default camera for a sphere about `centre` of `radius` seen in an image of width / height `aspect`: it looks at
// the centre from 30 degrees above and 30 degrees to the right of the +z axis (y up), with a 45-degree vertical
// field of view, from the distance at which the sphere fits the narrower field of view with 5% to spare; near and
// far hold the sphere. A radius of 0 (a mesh of one point) is framed as 1.
Camera framing_camera(const glm::vec3& centre, float radius, float aspect);

// The default light for that camera: white, intensity 1, no attenuation, no shadows, at the camera's distance from
// the centre, up and to the left of the view (a key light).
Light framing_light(const Camera& camera);

// Frames a scene whose file gave no camera (`camera`) or no light (`light`): framing_camera of the sphere about the
// centre of the box bounding its placed triangles' vertices through the farthest of them, and framing_light. Throws
// InputError naming the scene when no float camera can frame it.
void frame_scene(Scene& scene, bool camera, bool light);

// The scene of the mesh file `path`, read into `data`: the mesh with its OBJ materials (else the default material,
// its PLY colours showing), the default render settings, framing_camera of the sphere about the centre of its
// triangles' vertices' bounding box through the farthest of them, and framing_light. Relative names inside it (an
// MTL library, textures) resolve against its folder through `files`. Throws InputError naming the mesh file, also
// when no float camera can frame it.
void read_mesh_file_scene(MeshData data, const std::filesystem::path& path, const SceneFileLoaders& files,
                          Scene& scene);

}  // namespace raster
