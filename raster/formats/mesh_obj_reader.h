// Internal to raster_formats (mesh_obj.cpp): OBJ statements read and checked line by line, before triangulation.
#pragma once

#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace raster::obj {

inline constexpr uint32_t kNoNormal = std::numeric_limits<uint32_t>::max();
inline constexpr uint32_t kNoTexcoord = std::numeric_limits<uint32_t>::max();
inline constexpr uint32_t kNoMaterial = std::numeric_limits<uint32_t>::max();

// A face corner: 0-based indices into ObjStatements::positions, ::normals (kNoNormal when it names no normal) and
// ::texcoords (kNoTexcoord when it names none, or one the file does not have).
struct Corner {
    uint32_t position;
    uint32_t normal;
    uint32_t texcoord = kNoTexcoord;
};

// A face of `corner_count` (at least 3) corners, stored from `first_corner` on in ObjStatements::corners, with the
// material `usemtl` named before it (an index into ObjStatements::material_names, or kNoMaterial).
struct Face {
    size_t first_corner;
    size_t corner_count;
    uint32_t material = kNoMaterial;
};

// An object of the file (`o` or `g`): its faces run from `first_face` to the next object's first face.
struct Object {
    std::string name;
    size_t first_face;
};

// What a file's statements hold: every position (and colour, when every `v` has one), normal and face, and the
// objects in file order. Every face belongs to an object, and every index is in range.
struct ObjStatements {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> colors;
    std::vector<glm::vec3> normals;
    std::vector<glm::vec2> texcoords;  // `vt u [v [w]]`: u and v, a missing v or a value that is no number 0
    std::vector<Corner> corners;
    std::vector<Face> faces;
    std::vector<Object> objects;
    std::vector<std::string> material_names;      // distinct `usemtl` names, in order of first use
    std::vector<std::string> material_libraries;  // `mtllib` file names, in order, as written
    std::vector<int64_t> material_library_lines;  // the line of each
};

// Reads every line of `text` in one pass; `name` names the file in errors. Throws InputError, with the line, for
// anything that is not OBJ text: an unknown statement, a coordinate that is not a finite number, too few
// coordinates or corners, a corner that is not an index or names a vertex or normal the file does not have.
ObjStatements read_obj_statements(std::string_view text, const std::string& name);

}  // namespace raster::obj
