// Mesh data as loaded from a file or a scene: positions, optional attributes, triangles. Loaders produce it.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace raster {

// One indexed triangle: three indices into MeshData::positions (and normals/colors when present).
struct TriangleIndices {
    uint32_t v[3];
};

// The texture coordinates of one triangle's three corners (u right, v up, as OBJ and PLY have them).
struct TriangleUvs {
    glm::vec2 uv[3];
};

// OBJ `usemtl`: the triangles from first_triangle to the next run's first use the material `name` ("" before any
// usemtl).
struct MaterialRun {
    std::string name;
    uint32_t first_triangle = 0;
};

// OBJ `mtllib`: a material file as the mesh names it (relative to the mesh's folder), and the line naming it.
struct MaterialLibrary {
    std::string file;
    int64_t line = 0;
};

// A triangle mesh in object space. Optional attributes are either empty or exactly one per vertex / per face:
// a scene that does not use an attribute carries no storage for it.
struct MeshData {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;       // per vertex, optional (computed from faces when a shading mode needs it)
    std::vector<glm::vec3> colors;        // per vertex, linear RGB in [0,1], optional
    std::vector<glm::vec3> face_colors;   // per triangle, linear RGB in [0,1], optional
    std::vector<TriangleIndices> triangles;
    std::vector<TriangleUvs> corner_uvs;  // per triangle, optional: kept only when a material of the mesh is textured
    std::vector<std::string> object_names;      // names of the objects in the file (OBJ `o`/`g`), may be empty
    std::vector<uint32_t> object_first_triangle;  // first triangle index of each object, same length as names
    std::vector<MaterialRun> material_runs;            // OBJ usemtl; empty when the file names no material
    std::vector<MaterialLibrary> material_libraries;   // OBJ mtllib
};

// Limits every mesh loader enforces, so that hostile files fail cleanly instead of exhausting memory.
inline constexpr uint64_t kMaxMeshVertices = 1u << 24;   // 16.7M vertices
inline constexpr uint64_t kMaxMeshTriangles = 1u << 24;  // 16.7M triangles
inline constexpr uint64_t kMaxPolygonVertices = 1024;    // per face, before triangulation
// The most triangles a scene's meshes may hold together: the renderer's setup references name a frame's setups in
// 32 bits (geometry/setup_table.h).
inline constexpr uint64_t kMaxSceneTriangles = uint64_t{1} << 28;  // 268M triangles

}  // namespace raster
