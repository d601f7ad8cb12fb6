// Internal to raster_formats (the PLY reader): the PLY header grammar, its property types and its limits.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace raster::ply {

enum class Format { Ascii, BinaryLittleEndian };

enum class Type : uint8_t { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

// What a property means to the loader; everything else is read (validated in ascii) and dropped.
enum class Role : uint8_t { None, X, Y, Z, NX, NY, NZ, U, V, Red, Green, Blue, Indices };

struct Property {
    std::string name;
    bool is_list = false;
    Type count_type = Type::UInt8;  // lists only
    Type type = Type::Float32;      // scalar type, or item type of a list
    Role role = Role::None;
    int64_t line = 0;
};

struct Element {
    std::string name;
    uint64_t count = 0;
    std::vector<Property> properties;
    int64_t line = 0;
};

struct Header {
    Format format = Format::Ascii;
    std::vector<Element> elements;
    size_t body_offset = 0;  // byte offset of the first body byte in the file
    int64_t line_count = 0;  // number of header lines, end_header included
};

size_t type_size(Type t);
bool is_integer(Type t);
const char* type_name(Type t);  // as a header writes it: char, uchar, ..., double
int64_t type_min(Type t);       // integer types only
int64_t type_max(Type t);       // integer types only

// Parses the header at the start of `bytes` (`name` names the file in errors). Throws InputError with the line
// (and the column of the token at fault) on anything the grammar or its limits refuse, including a vertex or face
// count over the mesh limits, colours, normals or texture coordinates (u v, s t or texture_u texture_v) given in
// part or twice, and a `vertex` element without x, y and z.
// Blender 2.4x's `Created by ...` line without `comment` is read as a comment, with a warning on stderr.
Header parse_header(std::string_view bytes, const std::string& name);

}  // namespace raster::ply
