// The scene's geometry as the oracle sees it, from the loaded Scene alone, in double: every triangle by its scene
// id (meshes in order, each mesh's triangles in order), every vertex in world and view space, and for lit shading
// the documented vertex normals (docs/conventions.md), with how far raster's float versions of positions and normals can be from these.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "oracle/reference/camera.h"
#include "oracle/reference/camera_precision.h"
#include "oracle/reference/model_precision.h"
#include "raster/scene/scene.h"

namespace raster::oracle {

struct OracleTriangle {
    uint32_t mesh = 0;                   // index into scene.meshes
    uint32_t local = 0;                  // the triangle's index in its mesh
    std::array<uint32_t, 3> vertex{};    // global vertex indices (mesh_first_vertex[mesh] + the mesh's index)
};

struct OracleScene {
    OracleCamera camera;
    CameraMatrixError camera_error;      // raster's float camera matrices against `camera`
    std::vector<ModelMatrixError> models;  // per mesh: the oracle's model matrix and raster's error against it
    std::vector<OracleTriangle> triangles;
    std::vector<uint32_t> mesh_first_vertex;
    std::vector<glm::dvec3> world;       // per vertex: model * position
    std::vector<glm::dvec3> view;        // per vertex: the camera's view of `world`
    // Lit shading modes only (empty for unlit):
    std::vector<glm::dvec3> world_error;   // per vertex: raster's float world position, per component
    // Modes with vertex normals only (Gouraud, Phong, Blinn-Phong, cel, Gooch):
    std::vector<glm::dvec3> normal;        // per vertex: the unit normal (zero where none is defined)
    std::vector<double> normal_error;      // per vertex: how far raster's unit normal can be (2-norm)
};

// The material of a triangle, read by the oracle itself from the mesh's parts: the last part that starts at or
// before the triangle, else the mesh's own material.
const Material& triangle_material(const Scene& scene, const OracleTriangle& triangle);

// Whether the oracle takes a material's surfaces as transparent layers (docs/transparency.md): an opacity below 1,
// or a texture whose alpha the material reads (then each point's opacity is the shader's).
bool layered_material(const Material& material);

// Normals, as docs/conventions.md defines them: a file's normals by the inverse transpose of the model matrix, renormalised;
// without them, the normalised mean of the unit normals of the vertex's faces in world space (degenerate faces
// left out). Either is zero where it has no direction.
OracleScene oracle_scene(const Scene& scene);

// The scene's triangles seen by another camera into a width x height image (a shadow map's face): camera, its
// error bounds, triangles, world and view positions; no normals or attribute errors.
OracleScene oracle_view(const Scene& scene, const Camera& camera, int width, int height);

}  // namespace raster::oracle
