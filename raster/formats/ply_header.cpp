// The PLY header: its grammar line by line (format, elements, properties, their types and roles) and its limits.
#include "raster/formats/ply_header.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cstdio>
#include <limits>
#include <optional>
#include <system_error>

#include "raster/core/errors.h"
#include "raster/formats/mesh_text.h"
#include "raster/formats/ply_tokens.h"
#include "raster/scene/mesh.h"

namespace raster::ply {
namespace {

// Header sanity limits: no real PLY file comes close, and they bound the work a hostile header can cause.
constexpr size_t kMaxElements = 1024;
constexpr size_t kMaxPropertiesPerElement = 1024;

std::optional<Type> parse_type(std::string_view s) {
    struct Entry {
        std::string_view name;
        Type type;
    };
    static constexpr std::array<Entry, 16> kTypes{{
        {"char", Type::Int8},      {"int8", Type::Int8},       {"uchar", Type::UInt8},     {"uint8", Type::UInt8},
        {"short", Type::Int16},    {"int16", Type::Int16},     {"ushort", Type::UInt16},   {"uint16", Type::UInt16},
        {"int", Type::Int32},      {"int32", Type::Int32},     {"uint", Type::UInt32},     {"uint32", Type::UInt32},
        {"float", Type::Float32},  {"float32", Type::Float32}, {"double", Type::Float64},  {"float64", Type::Float64},
    }};
    for (const Entry& e : kTypes)
        if (e.name == s) return e.type;
    return std::nullopt;
}

class HeaderParser {
public:
    HeaderParser(std::string_view bytes, const std::string& name) : bytes_(bytes), name_(name) {}

    Header parse() {
        size_t pos = 0;
        bool have_format = false;
        int64_t line_no = 0;
        for (;;) {
            if (pos >= bytes_.size()) {
                fail(std::max<int64_t>(line_no, 1), 0,
                     line_no == 0 ? "not a PLY file: missing 'ply' magic (the file is empty)"
                                  : "truncated header: no 'end_header' line");
            }
            const size_t nl = bytes_.find('\n', pos);
            std::string_view line = bytes_.substr(pos, nl == std::string_view::npos ? std::string_view::npos : nl - pos);
            pos = nl == std::string_view::npos ? bytes_.size() : nl + 1;
            ++line_no;
            line_ = line;
            while (!line.empty() && is_space(line.back())) line.remove_suffix(1);  // CRLF and trailing blanks

            if (line_no == 1) {
                if (line != "ply") fail(1, 0, "not a PLY file: missing 'ply' magic on the first line");
                continue;
            }
            const std::vector<std::string_view> tok = split_words(line, is_space);
            if (tok.empty()) continue;  // blank header lines are tolerated
            const std::string_view keyword = tok[0];
            if (keyword == "comment" || keyword == "obj_info") continue;
            if (keyword == "Created" && tok.size() > 1 && tok[1] == "by") {
                // Blender 2.4x's exporter writes "Created by Blender 2.49 - www.blender.org, source file: ..."
                // without 'comment'. The readers users know take it as a comment; so does raster, and says so.
                std::fprintf(stderr,
                             "%s:%lld: warning: header line 'Created by ...' has no 'comment' keyword (Blender 2.4x "
                             "writes it so); read as a comment\n",
                             name_.c_str(), static_cast<long long>(line_no));
                continue;
            }
            if (keyword == "format") {
                parse_format(tok, line_no, have_format);
                have_format = true;
            } else if (keyword == "element") {
                parse_element(tok, line_no);
            } else if (keyword == "property") {
                parse_property(tok, line_no);
            } else if (keyword == "end_header") {
                if (tok.size() != 1) fail(line_no, tok[1], "unexpected text after 'end_header'");
                if (!have_format) fail(line_no, 0, "header has no 'format' line");
                header_.body_offset = pos;
                header_.line_count = line_no;
                validate(line_no);
                return std::move(header_);
            } else {
                fail(line_no, keyword, "unknown header keyword " + quote(keyword));
            }
        }
    }

private:
    [[noreturn]] void fail(int64_t line, int64_t column, const std::string& message) const {
        throw InputError(name_, clamp_int(line), clamp_int(column), message);
    }
    [[noreturn]] void fail(int64_t line, std::string_view token, const std::string& message) const {
        fail(line, static_cast<int64_t>(token.data() - line_.data()) + 1, message);
    }

    void parse_format(const std::vector<std::string_view>& tok, int64_t line_no, bool already) {
        if (already) fail(line_no, tok[0], "duplicate 'format' line");
        if (!header_.elements.empty()) fail(line_no, tok[0], "'format' must come before the first 'element'");
        if (tok.size() != 3) fail(line_no, tok[0], "expected 'format <ascii|binary_little_endian> 1.0'");
        if (tok[1] == "ascii") {
            header_.format = Format::Ascii;
        } else if (tok[1] == "binary_little_endian") {
            header_.format = Format::BinaryLittleEndian;
        } else if (tok[1] == "binary_big_endian") {
            fail(line_no, tok[1], "unsupported PLY format 'binary_big_endian' (only ascii and binary_little_endian)");
        } else {
            fail(line_no, tok[1], "unknown PLY format " + quote(tok[1]));
        }
        double version = 0;
        if (parse_double(tok[2], version) != NumberError::None || version != 1.0)
            fail(line_no, tok[2], "unsupported PLY version " + quote(tok[2]) + " (expected 1.0)");
    }

    void parse_element(const std::vector<std::string_view>& tok, int64_t line_no) {
        if (tok.size() != 3) fail(line_no, tok[0], "expected 'element <name> <count>'");
        if (header_.elements.size() >= kMaxElements)
            fail(line_no, tok[0], "too many elements (limit " + std::to_string(kMaxElements) + ")");
        const std::string_view name = tok[1];
        for (const Element& e : header_.elements)
            if (e.name == name) fail(line_no, tok[1], "duplicate element " + quote(name));
        const std::string_view count_text = strip_plus(tok[2]);
        uint64_t count = 0;
        const auto [end, ec] = std::from_chars(count_text.data(), count_text.data() + count_text.size(), count);
        const bool whole = end == count_text.data() + count_text.size();
        if (!count_text.empty() && count_text[0] == '-') {
            int64_t negative = 0;
            if (parse_int64(tok[2], negative) != NumberError::NotANumber)
                fail(line_no, tok[2], "negative count " + quote(tok[2]) + " for element " + quote(name));
        }
        if (ec == std::errc::result_out_of_range && whole)
            fail(line_no, tok[2], "element count " + quote(tok[2]) + " is too large");
        if (ec != std::errc() || !whole) fail(line_no, tok[2], "invalid element count " + quote(tok[2]));
        if (name == "vertex" && count > kMaxMeshVertices)
            fail(line_no, tok[2], "too many vertices: " + std::to_string(count) + " (limit " +
                                      std::to_string(kMaxMeshVertices) + ")");
        if (name == "face" && count > kMaxMeshTriangles)
            fail(line_no, tok[2], "too many faces: " + std::to_string(count) + " (limit " +
                                      std::to_string(kMaxMeshTriangles) + " triangles)");
        Element e;
        e.name = std::string(name);
        e.count = count;
        e.line = line_no;
        header_.elements.push_back(std::move(e));
    }

    Type expect_type(std::string_view token, int64_t line_no) const {
        const std::optional<Type> t = parse_type(token);
        if (!t) fail(line_no, token, "unknown property type " + quote(token));
        return *t;
    }

    void parse_property(const std::vector<std::string_view>& tok, int64_t line_no) {
        if (header_.elements.empty()) fail(line_no, tok[0], "'property' before any 'element'");
        Element& element = header_.elements.back();
        if (element.properties.size() >= kMaxPropertiesPerElement)
            fail(line_no, tok[0], "too many properties (limit " + std::to_string(kMaxPropertiesPerElement) + ")");
        Property p;
        p.line = line_no;
        std::string_view name_token;
        if (tok.size() >= 2 && tok[1] == "list") {
            if (tok.size() != 5) fail(line_no, tok[0], "expected 'property list <count type> <item type> <name>'");
            p.is_list = true;
            p.count_type = expect_type(tok[2], line_no);
            if (!is_integer(p.count_type))
                fail(line_no, tok[2], "list count type must be an integer type, not " + quote(tok[2]));
            p.type = expect_type(tok[3], line_no);
            name_token = tok[4];
        } else {
            if (tok.size() != 3) fail(line_no, tok[0], "expected 'property <type> <name>'");
            p.type = expect_type(tok[1], line_no);
            name_token = tok[2];
        }
        p.name = std::string(name_token);
        for (const Property& q : element.properties)
            if (q.name == p.name)
                fail(line_no, name_token, "duplicate property " + quote(name_token) + " in element " + quote(element.name));
        p.role = role_of(element.name, p.name);
        check_role(p, name_token, line_no);
        element.properties.push_back(std::move(p));
    }

    static Role role_of(std::string_view element, std::string_view property) {
        if (element == "vertex") {
            if (property == "x") return Role::X;
            if (property == "y") return Role::Y;
            if (property == "z") return Role::Z;
            if (property == "nx") return Role::NX;
            if (property == "ny") return Role::NY;
            if (property == "nz") return Role::NZ;
            // Texture coordinates under the names exporters use: u v (Blender, MeshLab), s t, texture_u texture_v.
            if (property == "u" || property == "s" || property == "texture_u") return Role::U;
            if (property == "v" || property == "t" || property == "texture_v") return Role::V;
        }
        if (element == "vertex" || element == "face") {
            if (property == "red") return Role::Red;
            if (property == "green") return Role::Green;
            if (property == "blue") return Role::Blue;
        }
        if (element == "face" && (property == "vertex_indices" || property == "vertex_index")) return Role::Indices;
        return Role::None;
    }

    void check_role(const Property& p, std::string_view token, int64_t line_no) const {
        switch (p.role) {
            case Role::None: return;
            case Role::Indices:
                if (!p.is_list) fail(line_no, token, "face property " + quote(token) + " must be a list");
                if (!is_integer(p.type))
                    fail(line_no, token, "vertex indices must have an integer type, not " + std::string(type_name(p.type)));
                return;
            case Role::Red:
            case Role::Green:
            case Role::Blue:
                if (p.is_list) fail(line_no, token, "colour property " + quote(token) + " must not be a list");
                if (p.type != Type::UInt8 && p.type != Type::UInt16 && is_integer(p.type))
                    fail(line_no, token, "unsupported colour type " + std::string(type_name(p.type)) +
                                             " (use uchar, ushort, float or double)");
                return;
            default:
                if (p.is_list) fail(line_no, token, "vertex property " + quote(token) + " must not be a list");
                return;
        }
    }

    void validate(int64_t end_line) const {
        const Element* vertex = nullptr;
        for (const Element& e : header_.elements) {
            auto has = [&](Role r) {
                return std::any_of(e.properties.begin(), e.properties.end(), [r](const Property& p) { return p.role == r; });
            };
            const int colours = int{has(Role::Red)} + int{has(Role::Green)} + int{has(Role::Blue)};
            if (colours != 0 && colours != 3)
                fail(e.line, 0, "element " + quote(e.name) + " has some but not all of red, green, blue");
            if (e.name == "vertex") {
                vertex = &e;
                if (!has(Role::X) || !has(Role::Y) || !has(Role::Z))
                    fail(e.line, 0, "element 'vertex' needs properties x, y and z");
                const int normals = int{has(Role::NX)} + int{has(Role::NY)} + int{has(Role::NZ)};
                if (normals != 0 && normals != 3) fail(e.line, 0, "element 'vertex' has some but not all of nx, ny, nz");
                int us = 0, vs = 0;
                for (const Property& p : e.properties) us += p.role == Role::U, vs += p.role == Role::V;
                if (us + vs != 0 && (us != 1 || vs != 1))
                    fail(e.line, 0, "element 'vertex' needs one u (u, s or texture_u) and one v (v, t or texture_v) "
                                    "for texture coordinates; it has " + std::to_string(us) + " and " + std::to_string(vs));
            } else if (e.name == "face") {
                if (!has(Role::Indices))
                    fail(e.line, 0, "element 'face' needs a list property 'vertex_indices' (or 'vertex_index')");
                int index_lists = 0;
                for (const Property& p : e.properties) index_lists += p.role == Role::Indices;
                if (index_lists > 1) fail(e.line, 0, "element 'face' has both 'vertex_indices' and 'vertex_index'");
            }
        }
        if (vertex == nullptr) fail(end_line, 0, "header declares no 'vertex' element");
    }

    std::string_view bytes_;
    const std::string& name_;
    std::string_view line_;  // current raw line, for columns
    Header header_;
};


}  // namespace

size_t type_size(Type t) {
    switch (t) {
        case Type::Int8:
        case Type::UInt8: return 1;
        case Type::Int16:
        case Type::UInt16: return 2;
        case Type::Int32:
        case Type::UInt32:
        case Type::Float32: return 4;
        case Type::Float64: return 8;
    }
    return 1;
}

bool is_integer(Type t) { return t != Type::Float32 && t != Type::Float64; }

const char* type_name(Type t) {
    switch (t) {
        case Type::Int8: return "char";
        case Type::UInt8: return "uchar";
        case Type::Int16: return "short";
        case Type::UInt16: return "ushort";
        case Type::Int32: return "int";
        case Type::UInt32: return "uint";
        case Type::Float32: return "float";
        case Type::Float64: return "double";
    }
    return "?";
}

int64_t type_min(Type t) {
    switch (t) {
        case Type::Int8: return std::numeric_limits<int8_t>::min();
        case Type::Int16: return std::numeric_limits<int16_t>::min();
        case Type::Int32: return std::numeric_limits<int32_t>::min();
        default: return 0;
    }
}

int64_t type_max(Type t) {
    switch (t) {
        case Type::Int8: return std::numeric_limits<int8_t>::max();
        case Type::UInt8: return std::numeric_limits<uint8_t>::max();
        case Type::Int16: return std::numeric_limits<int16_t>::max();
        case Type::UInt16: return std::numeric_limits<uint16_t>::max();
        case Type::Int32: return std::numeric_limits<int32_t>::max();
        case Type::UInt32: return std::numeric_limits<uint32_t>::max();
        default: return 0;
    }
}

Header parse_header(std::string_view bytes, const std::string& name) { return HeaderParser(bytes, name).parse(); }

}  // namespace raster::ply
