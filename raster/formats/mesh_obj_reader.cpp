// OBJ statements in one pass: each line is checked (naming its line when it is not OBJ text) and collected.
#include "raster/formats/mesh_obj_reader.h"

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <optional>
#include <utility>

#include "raster/core/errors.h"
#include "raster/formats/mesh_obj_numbers.h"
#include "raster/formats/mesh_text.h"
#include "raster/scene/mesh.h"

namespace raster::obj {
namespace {

using Words = std::vector<std::string_view>;

bool is_blank(char c) { return c == ' ' || c == '\t'; }

// OBJ words are separated by blanks only: a carriage return or NUL byte inside a line is part of a word.
Words split_words(std::string_view line) { return raster::split_words(line, is_blank); }

// Statements of the OBJ specification (and tinyobjloader's vw / t); anything else is not OBJ text.
bool known_statement(std::string_view keyword) {
    static constexpr std::string_view kKnown[] = {
        "v",   "vt",      "vn",    "vp",   "f",     "l",     "p",        "o",        "g",          "s",
        "mg",  "usemtl",  "mtllib", "cstype", "deg", "bmat",  "step",     "curv",     "curv2",      "surf",
        "parm", "trim",   "hole",  "scrv", "sp",    "end",   "con",      "call",     "csh",        "bevel",
        "c_interp", "d_interp", "lod", "shadow_obj", "trace_obj", "ctech", "stech", "maplib", "usemap", "vw", "t"};
    return std::find(std::begin(kKnown), std::end(kKnown), keyword) != std::end(kKnown);
}

// An index as the checks read it: strtol over the whole part, which ends early at a NUL byte as a C string does.
// The usual part, a sign and at most 18 digits, is read here to the same value without copying it for strtol.
std::optional<long> index_in(std::string_view part) {
    if (part.empty()) return std::nullopt;
    const size_t sign = part[0] == '-' || part[0] == '+' ? 1 : 0;
    if (part.size() > sign && part.size() - sign <= 18 && std::all_of(part.begin() + sign, part.end(), is_digit)) {
        long value = 0;
        for (size_t k = sign; k < part.size(); ++k) value = value * 10 + (part[k] - '0');
        return part[0] == '-' ? -value : value;
    }
    const std::string text(part);
    char* end = nullptr;
    errno = 0;
    const long index = std::strtol(text.c_str(), &end, 10);
    if (*end != '\0' || errno == ERANGE) return std::nullopt;
    return index;
}

// The parts of a face corner between its '/'s: at most 3 are kept, and a fourth only counted.
struct CornerParts {
    std::array<std::string_view, 3> part;
    size_t count = 0;
};

CornerParts split_corner(std::string_view corner) {
    CornerParts parts;
    for (size_t start = 0;;) {
        const size_t slash = corner.find('/', start);
        if (parts.count == 3) {
            parts.count = 4;
            return parts;
        }
        parts.part[parts.count++] = corner.substr(start, slash == std::string_view::npos ? slash : slash - start);
        if (slash == std::string_view::npos) return parts;
        start = slash + 1;
    }
}

class StatementReader {
public:
    StatementReader(std::string_view text, const std::string& name) : text_(text), name_(name) {}

    ObjStatements read() {
        for (size_t start = 0; start < text_.size();) {
            size_t end = text_.find('\n', start);
            if (end == std::string_view::npos) end = text_.size();
            std::string_view line = text_.substr(start, end - start);
            start = end + 1;
            ++line_number_;
            if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
            read_line(line);
            carriage_returns_before_ += std::count(line.begin(), line.end(), '\r');
        }
        end_group(GroupEnd::by_file);
        check_forward_references();
        if (tinyobj_error_) throw InputError(name_, clamped(tinyobj_error_->first), 0, tinyobj_error_->second);
        if (!every_vertex_coloured_) out_.colors.clear();
        return std::move(out_);
    }

private:
    enum class GroupEnd { by_object, by_group, by_file };

    // The object (`o`) or group (`g`) being read, and what decides whether it is kept when it ends.
    struct OpenGroup {
        std::string name;
        size_t first_face = 0;
        bool has_statements = false;  // an f, l or p statement, even one that gives no triangle
        bool has_line_corners = false;
    };

    struct ForwardReference {
        int64_t line;
        long index;
        bool normal;
    };

    // Lines are counted in 64 bits (a 2 GiB file can hold 2^31 of them) and clamped for InputError.
    static int clamped(int64_t line) { return static_cast<int>(std::min<int64_t>(line, std::numeric_limits<int>::max())); }

    [[noreturn]] void fail(const std::string& message) const {
        throw InputError(name_, clamped(line_number_), 0, message);
    }

    // tinyobjloader refused some statements the line checks let through (a texture index that reads as 0, an `l`,
    // `p` or `vw` it could not read). Its refusal came after every line check, in its own words, on a line of its
    // own count (to which a carriage return alone is a line break), and these keep all three.
    void refuse_as_tinyobjloader(const std::string& message) {
        if (tinyobj_error_) return;
        const int64_t line = line_number_ + carriage_returns_before_;
        tinyobj_error_.emplace(line, message + " line " + std::to_string(line) + ".)");
    }

    void read_line(std::string_view line) {
        const Words words = split_words(line);
        if (words.empty() || words[0][0] == '#') return;
        const std::string_view keyword = words[0];
        if (!known_statement(keyword)) {
            std::string shown(keyword.substr(0, 32));
            for (char& c : shown)
                if (static_cast<unsigned char>(c) < 32 || static_cast<unsigned char>(c) > 126) c = '?';
            fail("not an OBJ statement: '" + shown + "'");
        }
        // The statement is read from the line up to its first NUL byte or carriage return, which is where
        // tinyobjloader's reading of the line ended, while the checks above and below cover the whole line.
        const std::string_view visible = line.substr(0, std::min(line.find('\0'), line.find('\r')));
        const std::string_view statement = visible.substr(visible.find_first_not_of(" \t"));
        // tinyobjloader took the keywords l, p, vw, o and g for a statement only when a blank follows them.
        const bool has_rest = statement.size() > keyword.size();
        const std::string_view rest = has_rest ? statement.substr(keyword.size() + 1) : std::string_view();
        if (keyword == "v") {
            read_vertex(words);
        } else if (keyword == "vn") {
            read_normal(words);
        } else if (keyword == "vt") {
            read_texcoord(words);
        } else if (keyword == "usemtl" && has_rest) {
            use_material(rest);
        } else if (keyword == "mtllib" && has_rest) {
            for (const std::string_view library : split_words(rest)) {
                out_.material_libraries.emplace_back(library);
                out_.material_library_lines.push_back(line_number_);
            }
        } else if (keyword == "f") {
            read_face(words, visible, visible.size() < line.size());
        } else if ((keyword == "l" || keyword == "p") && has_rest) {
            read_corner_list(keyword, rest);
        } else if (keyword == "vw" && has_rest) {
            if (!reads_skin_weights(rest)) refuse_as_tinyobjloader("Failed parse `vw' line. joint_id is negative.");
        } else if (keyword == "o" && has_rest) {
            end_group(GroupEnd::by_object);
            group_.name = std::string(rest);
        } else if (keyword == "g" && has_rest) {
            end_group(GroupEnd::by_group);
            const Words names = split_words(rest);
            for (size_t k = 0; k < names.size(); ++k) {
                if (k > 0) group_.name += ' ';
                group_.name += names[k];
            }
        }
    }

    // A plain decimal, [+-]digits[.digits] or [+-].digits with at most 30 digits before the point: strtod reads it
    // whole, finite and within float's range, so checked_coordinate need not run strtod on it.
    static bool plain_decimal(std::string_view word) {
        size_t at = !word.empty() && (word[0] == '+' || word[0] == '-') ? 1 : 0;
        size_t whole = 0, fraction = 0;
        for (; at < word.size() && is_digit(word[at]); ++at) ++whole;
        if (at < word.size() && word[at] == '.')
            for (++at; at < word.size() && is_digit(word[at]); ++at) ++fraction;
        return at == word.size() && whole + fraction > 0 && whole <= 30;
    }

    // Refuses a word strtod does not read whole, or reads as a value beyond float's range.
    void checked_coordinate(std::string_view word) const {
        if (plain_decimal(word)) return;
        const std::string text(word);
        char* end = nullptr;
        const double value = std::strtod(text.c_str(), &end);
        if (end != text.c_str() + text.size()) fail("'" + text + "' is not a number");
        if (!std::isfinite(value) || std::fabs(value) > 3.0e38) fail("'" + text + "' is not a finite number");
    }

    // The coordinates of a `v` or `vn`: every word after the keyword must be a number by strtod (at least 3 of
    // them); the values are tinyobjloader's (number_value), which gives no value for a few numbers strtod reads.
    std::array<std::optional<double>, 6> read_coordinates(const Words& words, const char* what) const {
        if (words.size() < 4)
            fail(std::string(what) + " needs 3 coordinates, has " + std::to_string(words.size() - 1));
        std::array<std::optional<double>, 6> values;
        for (size_t k = 1; k < words.size(); ++k) {
            checked_coordinate(words[k]);
            if (k <= values.size()) values[k - 1] = number_value(words[k]);
        }
        return values;
    }

    static glm::vec3 vec3_of(const std::optional<double>* values) {
        return glm::vec3(static_cast<float>(values[0].value_or(0.0)), static_cast<float>(values[1].value_or(0.0)),
                         static_cast<float>(values[2].value_or(0.0)));
    }

    void read_vertex(const Words& words) {
        const auto values = read_coordinates(words, "a vertex");
        out_.positions.push_back(vec3_of(&values[0]));
        // `v x y z r g b`: colours are kept only when every vertex has all three.
        every_vertex_coloured_ = every_vertex_coloured_ && values[3] && values[4] && values[5];
        if (every_vertex_coloured_) out_.colors.push_back(vec3_of(&values[3]));
    }

    void read_normal(const Words& words) {
        const auto values = read_coordinates(words, "a normal");
        out_.normals.push_back(vec3_of(&values[0]));
    }

    // Texture coordinates are read as tinyobjloader read them, never refused: a value that is not a number is 0.
    void read_texcoord(const Words& words) {
        glm::vec2 uv(0.0f);
        for (size_t k = 1; k < std::min<size_t>(words.size(), 3); ++k) {
            const std::optional<double> value = number_value(words[k]);
            const double v = value && std::isfinite(*value) && std::fabs(*value) <= 3.0e38 ? *value : 0.0;
            uv[static_cast<int>(k - 1)] = static_cast<float>(v);
        }
        out_.texcoords.push_back(uv);
    }

    // `usemtl name`: the faces that follow use material `name` (the rest of the line, as tinyobjloader took it).
    void use_material(std::string_view rest) {
        const std::string name(rest);
        const auto known = std::find(out_.material_names.begin(), out_.material_names.end(), name);
        material_ = static_cast<uint32_t>(known - out_.material_names.begin());
        if (known == out_.material_names.end()) out_.material_names.push_back(name);
    }

    // A corner's texture index, when it names a texture coordinate the file has defined so far.
    std::optional<uint32_t> texcoord_index(std::string_view part) const {
        const std::optional<long> index = index_in(part);
        const long count = static_cast<long>(out_.texcoords.size());
        if (!index || *index == 0 || *index > count || *index < -count) return std::nullopt;
        return static_cast<uint32_t>(*index > 0 ? *index - 1 : count + *index);
    }

    // Reads corner `word` (v, v/vt, v//vn or v/vt/vn) into `corner`, or returns what is wrong with it. A texture
    // index is kept when it names a coordinate defined before it and otherwise dropped, never refused (as
    // tinyobjloader read them); `forward` collects position and normal indices past what is defined so far.
    std::optional<std::string> read_corner(std::string_view word, Corner& corner, bool& has_texture,
                                           std::vector<ForwardReference>* forward) const {
        const std::string shown(word);
        const CornerParts parts = split_corner(word);
        if (parts.count > 3) return "face corner '" + shown + "' has more than 3 parts";
        for (size_t part = 0; part < parts.count; part += 2) {
            const bool normal = part == 2;
            if (normal && parts.part[2].empty()) return "face corner '" + shown + "' has an empty normal index";
            const std::optional<long> index = index_in(parts.part[part]);
            if (!index) return "face corner '" + shown + "' is not a vertex index";
            const size_t count = normal ? out_.normals.size() : out_.positions.size();
            if (*index == 0) return "face corner '" + shown + "': OBJ indices start at 1";
            if (*index < -static_cast<long>(count))
                return "face corner '" + shown + "': relative index " + std::to_string(*index) + " but only " +
                       std::to_string(count) + (normal ? " normals" : " vertices") + " precede it";
            if (*index > 0 && static_cast<size_t>(*index) > count && forward)
                forward->push_back({line_number_, *index, normal});
            const auto resolved = static_cast<uint32_t>(*index > 0 ? *index - 1 : static_cast<long>(count) + *index);
            (normal ? corner.normal : corner.position) = resolved;
        }
        has_texture = parts.count == 2 || (parts.count == 3 && !parts.part[1].empty());
        if (has_texture) corner.texcoord = texcoord_index(parts.part[1]).value_or(kNoTexcoord);
        return std::nullopt;
    }

    // Every corner of the line is checked; the corners collected are those of `visible`, the part of the line
    // tinyobjloader read, which is the whole line unless `cut` (at a NUL byte or carriage return). tinyobjloader
    // also refused a face with a texture index that reads as 0 by atoi, which reads on into the next corner when
    // the index is empty ("1/ 2 3" reads 2): reads_corner does the same on the visible text.
    void read_face(const Words& words, std::string_view visible, bool cut) {
        if (words.size() < 4) fail("a face needs at least 3 vertices, has " + std::to_string(words.size() - 1));
        if (words.size() - 1 > kMaxPolygonVertices)
            fail("a face has " + std::to_string(words.size() - 1) + " vertices, more than " +
                 std::to_string(kMaxPolygonVertices));
        const size_t first_corner = out_.corners.size();
        auto tinyobj_reads = [&](std::string_view word) {
            size_t at = static_cast<size_t>(word.data() - visible.data());
            return reads_corner(visible, at);
        };
        for (size_t k = 1; k < words.size(); ++k) {
            Corner corner{0, kNoNormal};
            bool has_texture = false;
            if (const auto problem = read_corner(words[k], corner, has_texture, &forward_references_)) fail(*problem);
            if (cut) continue;
            if (has_texture && !tinyobj_reads(words[k]))
                refuse_as_tinyobjloader("Failed parse `f' line(e.g. zero value for face index.");
            out_.corners.push_back(corner);
        }
        const Words visible_words = cut ? split_words(visible) : Words{};
        for (size_t k = 1; k < visible_words.size(); ++k) {
            Corner corner{0, kNoNormal};
            bool has_texture = false;
            if (!tinyobj_reads(visible_words[k]) || read_corner(visible_words[k], corner, has_texture, nullptr))
                refuse_as_tinyobjloader("Failed parse `f' line(e.g. zero value for face index.");
            out_.corners.push_back(corner);
        }
        group_.has_statements = true;
        const size_t corner_count = out_.corners.size() - first_corner;
        if (corner_count >= 3) {
            out_.faces.push_back({first_corner, corner_count, material_});
        } else {
            out_.corners.resize(first_corner);  // tinyobjloader skipped a face it saw fewer than 3 corners of
        }
    }

    void read_corner_list(std::string_view keyword, std::string_view rest) {
        group_.has_statements = true;
        if (!reads_corner_list(rest, group_.has_line_corners))
            refuse_as_tinyobjloader("Failed parse `" + std::string(keyword) +
                                    "' line(e.g. zero value for vertex index.");
    }

    // tinyobjloader's rule for which objects the file has: an `o` keeps the one before it when it has triangles or
    // an `l` or `p` corner, a `g` only when it has triangles, and the end of the file keeps the last one when it has
    // any f, l or p statement at all. The faces before the first `o` or `g` are an object named "".
    void end_group(GroupEnd how) {
        const bool has_faces = out_.faces.size() > group_.first_face;
        const bool kept = how == GroupEnd::by_object  ? has_faces || group_.has_line_corners
                          : how == GroupEnd::by_group ? has_faces
                                                      : group_.has_statements;
        if (kept) out_.objects.push_back({std::move(group_.name), group_.first_face});
        group_ = OpenGroup{};
        group_.first_face = out_.faces.size();
    }

    void check_forward_references() const {
        for (const ForwardReference& ref : forward_references_) {
            const size_t count = ref.normal ? out_.normals.size() : out_.positions.size();
            if (static_cast<size_t>(ref.index) > count)
                throw InputError(name_, clamped(ref.line), 0,
                                 std::string("face uses ") + (ref.normal ? "normal " : "vertex ") +
                                     std::to_string(ref.index) + " but the file has " + std::to_string(count));
        }
    }

    std::string_view text_;
    const std::string& name_;
    int64_t line_number_ = 0;
    int64_t carriage_returns_before_ = 0;
    ObjStatements out_;
    OpenGroup group_;
    bool every_vertex_coloured_ = true;
    uint32_t material_ = kNoMaterial;
    std::vector<ForwardReference> forward_references_;
    std::optional<std::pair<int64_t, std::string>> tinyobj_error_;
};

}  // namespace

ObjStatements read_obj_statements(std::string_view text, const std::string& name) {
    return StatementReader(text, name).read();
}

}  // namespace raster::obj
