// Stanford PLY loader: header parser, ascii and binary little-endian body readers, fan triangulation, limits.
#include "raster/formats/mesh_ply.h"

#include <algorithm>
#include <array>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "raster/core/errors.h"

namespace raster {
namespace {

// Header sanity limits: no real PLY file comes close, and they bound the work a hostile header can cause.
constexpr size_t kMaxElements = 1024;
constexpr size_t kMaxPropertiesPerElement = 1024;
constexpr uint64_t kMaxFileBytes = uint64_t{1} << 31;  // 2 GiB

enum class Format { Ascii, BinaryLittleEndian };

enum class Type : uint8_t { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

// What a property means to the loader; everything else is read (validated in ascii) and dropped.
enum class Role : uint8_t { None, X, Y, Z, NX, NY, NZ, Red, Green, Blue, Indices };

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

// Line and column numbers are counted in 64 bits and clamped when handed to InputError (int).
int clamp_int(int64_t v) { return static_cast<int>(std::min<int64_t>(v, std::numeric_limits<int>::max())); }

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

// Makes file text safe for an error message: printable ASCII kept, everything else escaped, long text cut.
std::string printable(std::string_view s) {
    constexpr size_t kMaxShown = 40;
    std::string out;
    for (size_t i = 0; i < s.size() && i < kMaxShown; ++i) {
        const auto c = static_cast<unsigned char>(s[i]);
        if (c >= 0x20 && c < 0x7f && c != '\'') {
            out += static_cast<char>(c);
        } else {
            static constexpr char kHex[] = "0123456789abcdef";
            out += "\\x";
            out += kHex[c >> 4];
            out += kHex[c & 15];
        }
    }
    if (s.size() > kMaxShown) out += "...";
    return out;
}

std::string quote(std::string_view s) { return "'" + printable(s) + "'"; }

std::vector<std::string_view> split(std::string_view line) {
    std::vector<std::string_view> tokens;
    size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && is_space(line[i])) ++i;
        const size_t start = i;
        while (i < line.size() && !is_space(line[i])) ++i;
        if (i > start) tokens.push_back(line.substr(start, i - start));
    }
    return tokens;
}

// Strips one leading '+' (from_chars does not accept it) unless a sign follows it.
std::string_view strip_plus(std::string_view s) {
    if (s.size() >= 2 && s[0] == '+' && s[1] != '-' && s[1] != '+') s.remove_prefix(1);
    return s;
}

enum class NumberError { None, NotANumber, OutOfRange };

NumberError parse_int64(std::string_view token, int64_t& out) {
    const std::string_view s = strip_plus(token);
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
    if (ec == std::errc::result_out_of_range && end == s.data() + s.size()) return NumberError::OutOfRange;
    if (ec != std::errc() || end != s.data() + s.size()) return NumberError::NotANumber;
    return NumberError::None;
}

NumberError parse_double(std::string_view token, double& out) {
    const std::string_view s = strip_plus(token);
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), out, std::chars_format::general);
    if (end != s.data() + s.size() || (ec != std::errc() && ec != std::errc::result_out_of_range))
        return NumberError::NotANumber;
    if (ec == std::errc::result_out_of_range) {
        // libstdc++ also reports underflow as out of range: a negative exponent means the value is (nearly) zero.
        const bool negative_exponent = s.find("e-") != std::string_view::npos || s.find("E-") != std::string_view::npos;
        if (!negative_exponent) return NumberError::OutOfRange;
        out = s[0] == '-' ? -0.0 : 0.0;
    }
    return NumberError::None;
}

uint64_t saturating_mul(uint64_t a, uint64_t b) {
    if (a != 0 && b > std::numeric_limits<uint64_t>::max() / a) return std::numeric_limits<uint64_t>::max();
    return a * b;
}

// ---------------------------------------------------------------------------------------------------------------
// Header

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
            const std::vector<std::string_view> tok = split(line);
            if (tok.empty()) continue;  // blank header lines are tolerated
            const std::string_view keyword = tok[0];
            if (keyword == "comment" || keyword == "obj_info") continue;
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

// The fewest body bytes one instance of `e` can occupy (ascii: one byte less for the file's very last token).
uint64_t min_instance_bytes(const Element& e, Format format) {
    uint64_t bytes = 0;
    if (format == Format::BinaryLittleEndian) {
        for (const Property& p : e.properties) {
            uint64_t b = p.is_list ? type_size(p.count_type) : type_size(p.type);
            if (p.role == Role::Indices) b += 3 * type_size(p.type);  // a face has at least 3 indices
            bytes += b;
        }
    } else {
        // Every token is at least one character followed by one separator (the very last may lack it: +1 slack).
        for (const Property& p : e.properties) bytes += p.role == Role::Indices ? 2 * 4 : 2;
    }
    return bytes;
}

// ---------------------------------------------------------------------------------------------------------------
// Body readers. Both offer: begin_instance, read_scalar (as double), read_integer, skip_list_items, end_instance,
// finish, and fail (which throws with the location of the last value read).

class AsciiReader {
public:
    AsciiReader(std::string_view body, int64_t first_line, const std::string& name)
        : body_(body), next_line_no_(first_line), name_(name) {}

    void begin_instance(const Element& e, uint64_t index) {
        if (!next_nonblank_line())
            throw InputError(name_, clamp_int(next_line_no_), 0,
                             "truncated body: file ends before " + printable(e.name) + " " + std::to_string(index) + " (0-based) of " +
                                 std::to_string(e.count));
        element_ = &e;
        index_ = index;
    }

    void end_instance() {
        skip_space();
        if (line_pos_ < line_.size()) {
            column_ = static_cast<int64_t>(line_pos_) + 1;
            fail("extra tokens at the end of the line for " + printable(element_->name) + " " + std::to_string(index_) +
                 " (0-based): " + quote(line_.substr(line_pos_)));
        }
    }

    void finish() {
        if (next_nonblank_line()) {
            skip_space();
            column_ = static_cast<int64_t>(line_pos_) + 1;
            fail("unexpected data after the last element: " + quote(line_.substr(line_pos_)));
        }
    }

    double read_scalar(Type t) {
        const std::string_view tok = next_token();
        if (is_integer(t)) return static_cast<double>(integer_from(tok, t));
        double v = 0;
        switch (parse_double(tok, v)) {
            case NumberError::None: return v;
            case NumberError::OutOfRange: fail("number " + quote(tok) + " is out of range");
            case NumberError::NotANumber: break;
        }
        fail("expected a number, got " + quote(tok));
    }

    int64_t read_integer(Type t) { return integer_from(next_token(), t); }

    void skip_list_items(Type t, int64_t count) {
        for (int64_t i = 0; i < count; ++i) read_scalar(t);  // each item consumes a token or throws: bounded by the line
    }

    [[noreturn]] void fail(const std::string& message) const { throw InputError(name_, clamp_int(line_no_), clamp_int(column_), message);
    }

private:
    int64_t integer_from(std::string_view tok, Type t) {
        int64_t v = 0;
        switch (parse_int64(tok, v)) {
            case NumberError::None: break;
            case NumberError::OutOfRange: fail("integer " + quote(tok) + " is out of range for type " + type_name(t));
            case NumberError::NotANumber: fail("expected an integer (" + std::string(type_name(t)) + "), got " + quote(tok));
        }
        if (v < type_min(t) || v > type_max(t))
            fail("integer " + quote(tok) + " is out of range for type " + type_name(t));
        return v;
    }

    std::string_view next_token() {
        skip_space();
        if (line_pos_ >= line_.size()) {
            column_ = static_cast<int64_t>(line_.size()) + 1;
            fail("line ends early: " + printable(element_->name) + " " + std::to_string(index_) +
                 " (0-based) needs more values");
        }
        const size_t start = line_pos_;
        while (line_pos_ < line_.size() && !is_space(line_[line_pos_])) ++line_pos_;
        column_ = static_cast<int64_t>(start) + 1;
        return line_.substr(start, line_pos_ - start);
    }

    void skip_space() {
        while (line_pos_ < line_.size() && is_space(line_[line_pos_])) ++line_pos_;
    }

    bool next_nonblank_line() {
        while (pos_ < body_.size()) {
            const size_t nl = body_.find('\n', pos_);
            const size_t end = nl == std::string_view::npos ? body_.size() : nl;
            line_ = body_.substr(pos_, end - pos_);
            pos_ = nl == std::string_view::npos ? body_.size() : nl + 1;
            line_no_ = next_line_no_++;
            line_pos_ = 0;
            column_ = 0;
            skip_space();
            if (line_pos_ < line_.size()) return true;
        }
        return false;
    }

    std::string_view body_;
    size_t pos_ = 0;
    int64_t next_line_no_;
    int64_t line_no_ = 0;
    std::string_view line_;
    size_t line_pos_ = 0;
    int64_t column_ = 0;
    const Element* element_ = nullptr;
    uint64_t index_ = 0;
    const std::string& name_;
};

class BinaryReader {
public:
    BinaryReader(std::string_view body, size_t body_offset, const std::string& name)
        : body_(body), base_(body_offset), name_(name) {}

    void begin_instance(const Element& e, uint64_t index) {
        element_ = &e;
        index_ = index;
    }
    void end_instance() {}

    void finish() {
        value_pos_ = pos_;
        if (pos_ != body_.size())
            fail(std::to_string(body_.size() - pos_) + " unexpected bytes after the last element");
    }

    double read_scalar(Type t) {
        const uint64_t bits = take(t);
        switch (t) {
            case Type::Int8: return static_cast<int8_t>(bits);
            case Type::UInt8:
            case Type::UInt16:
            case Type::UInt32: return static_cast<double>(bits);
            case Type::Int16: return static_cast<int16_t>(bits);
            case Type::Int32: return static_cast<int32_t>(bits);
            case Type::Float32: {
                const auto u = static_cast<uint32_t>(bits);
                float f;
                std::memcpy(&f, &u, sizeof f);
                return f;
            }
            case Type::Float64: {
                double d;
                std::memcpy(&d, &bits, sizeof d);
                return d;
            }
        }
        return 0;
    }

    int64_t read_integer(Type t) { return static_cast<int64_t>(read_scalar(t)); }  // integer types only: exact

    void skip_list_items(Type t, int64_t count) {
        value_pos_ = pos_;
        const uint64_t bytes = saturating_mul(static_cast<uint64_t>(count), type_size(t));
        if (bytes > body_.size() - pos_) truncated();
        pos_ += bytes;
    }

    [[noreturn]] void fail(const std::string& message) const {
        throw InputError(name_, 0, 0, message + " (at byte offset " + std::to_string(base_ + value_pos_) + ")");
    }

private:
    uint64_t take(Type t) {
        value_pos_ = pos_;
        const size_t n = type_size(t);
        if (n > body_.size() - pos_) truncated();
        uint64_t bits = 0;
        for (size_t i = 0; i < n; ++i) bits |= uint64_t{static_cast<unsigned char>(body_[pos_ + i])} << (8 * i);
        pos_ += n;
        return bits;
    }

    [[noreturn]] void truncated() const {
        fail("truncated body: file ends inside " + printable(element_->name) + " " + std::to_string(index_) + " (0-based) of " +
             std::to_string(element_->count));
    }

    std::string_view body_;
    size_t base_;
    size_t pos_ = 0;
    size_t value_pos_ = 0;
    const Element* element_ = nullptr;
    uint64_t index_ = 0;
    const std::string& name_;
};

// ---------------------------------------------------------------------------------------------------------------
// Body

template <class Reader>
float finite_float(Reader& r, double v, const char* what) {
    if (!std::isfinite(v)) r.fail(std::string("non-finite ") + what);
    if (std::fabs(v) > static_cast<double>(std::numeric_limits<float>::max()))
        r.fail(std::string(what) + " is out of the float range");
    return static_cast<float>(v);
}

template <class Reader>
float colour_channel(Reader& r, double v, Type t) {
    if (t == Type::UInt8) return static_cast<float>(v / 255.0);
    if (t == Type::UInt16) return static_cast<float>(v / 65535.0);
    if (!std::isfinite(v)) r.fail("non-finite colour value");
    return static_cast<float>(std::clamp(v, 0.0, 1.0));
}

template <class Reader>
int64_t read_list_count(Reader& r, Type t) {
    const int64_t n = r.read_integer(t);
    if (n < 0) r.fail("negative list count " + std::to_string(n));
    return n;
}

template <class Reader>
void skip_element(Reader& r, const Element& e) {
    if (e.properties.empty()) return;  // occupies no bytes and no tokens
    for (uint64_t i = 0; i < e.count; ++i) {
        r.begin_instance(e, i);
        for (const Property& p : e.properties) {
            if (p.is_list)
                r.skip_list_items(p.type, read_list_count(r, p.count_type));
            else
                r.read_scalar(p.type);
        }
        r.end_instance();
    }
}

template <class Reader>
void read_vertices(Reader& r, const Element& e, size_t reserve, MeshData& mesh) {
    const bool has_colour = std::any_of(e.properties.begin(), e.properties.end(),
                                        [](const Property& p) { return p.role == Role::Red; });
    const bool has_normal = std::any_of(e.properties.begin(), e.properties.end(),
                                        [](const Property& p) { return p.role == Role::NX; });
    mesh.positions.reserve(reserve);
    if (has_colour) mesh.colors.reserve(reserve);
    if (has_normal) mesh.normals.reserve(reserve);
    for (uint64_t i = 0; i < e.count; ++i) {
        r.begin_instance(e, i);
        glm::vec3 position(0.0f), normal(0.0f), colour(0.0f);
        for (const Property& p : e.properties) {
            if (p.is_list) {
                r.skip_list_items(p.type, read_list_count(r, p.count_type));
                continue;
            }
            const double v = r.read_scalar(p.type);
            switch (p.role) {
                case Role::X: position.x = finite_float(r, v, "x coordinate"); break;
                case Role::Y: position.y = finite_float(r, v, "y coordinate"); break;
                case Role::Z: position.z = finite_float(r, v, "z coordinate"); break;
                case Role::NX: normal.x = finite_float(r, v, "normal nx"); break;
                case Role::NY: normal.y = finite_float(r, v, "normal ny"); break;
                case Role::NZ: normal.z = finite_float(r, v, "normal nz"); break;
                case Role::Red: colour.x = colour_channel(r, v, p.type); break;
                case Role::Green: colour.y = colour_channel(r, v, p.type); break;
                case Role::Blue: colour.z = colour_channel(r, v, p.type); break;
                default: break;
            }
        }
        r.end_instance();
        mesh.positions.push_back(position);
        if (has_colour) mesh.colors.push_back(colour);
        if (has_normal) mesh.normals.push_back(normal);
    }
}

template <class Reader>
void read_faces(Reader& r, const Element& e, uint64_t vertex_count, size_t reserve, MeshData& mesh) {
    const bool has_colour = std::any_of(e.properties.begin(), e.properties.end(),
                                        [](const Property& p) { return p.role == Role::Red; });
    mesh.triangles.reserve(reserve);  // at least one triangle per face
    if (has_colour) mesh.face_colors.reserve(reserve);
    std::vector<uint32_t> polygon;
    polygon.reserve(kMaxPolygonVertices);
    for (uint64_t i = 0; i < e.count; ++i) {
        r.begin_instance(e, i);
        polygon.clear();
        glm::vec3 colour(0.0f);
        for (const Property& p : e.properties) {
            if (p.role == Role::Indices) {
                const int64_t n = read_list_count(r, p.count_type);
                if (n < 3)
                    r.fail("face " + std::to_string(i) + " (0-based) has " + std::to_string(n) +
                           " vertices; a polygon needs at least 3");
                if (static_cast<uint64_t>(n) > kMaxPolygonVertices)
                    r.fail("face " + std::to_string(i) + " (0-based) has " + std::to_string(n) + " vertices (limit " +
                           std::to_string(kMaxPolygonVertices) + ")");
                for (int64_t k = 0; k < n; ++k) {
                    const int64_t index = r.read_integer(p.type);
                    if (index < 0 || static_cast<uint64_t>(index) >= vertex_count)
                        r.fail("face " + std::to_string(i) + " (0-based): vertex index " + std::to_string(index) +
                               " out of range (the file has " + std::to_string(vertex_count) + " vertices)");
                    polygon.push_back(static_cast<uint32_t>(index));
                }
            } else if (p.is_list) {
                r.skip_list_items(p.type, read_list_count(r, p.count_type));
            } else {
                const double v = r.read_scalar(p.type);
                switch (p.role) {
                    case Role::Red: colour.x = colour_channel(r, v, p.type); break;
                    case Role::Green: colour.y = colour_channel(r, v, p.type); break;
                    case Role::Blue: colour.z = colour_channel(r, v, p.type); break;
                    default: break;
                }
            }
        }
        r.end_instance();
        const size_t new_triangles = polygon.size() - 2;
        if (mesh.triangles.size() + new_triangles > kMaxMeshTriangles)
            r.fail("too many triangles after triangulating face " + std::to_string(i) + " (limit " +
                   std::to_string(kMaxMeshTriangles) + ")");
        for (size_t k = 1; k + 1 < polygon.size(); ++k) mesh.triangles.push_back({{polygon[0], polygon[k], polygon[k + 1]}});
        if (has_colour) mesh.face_colors.insert(mesh.face_colors.end(), new_triangles, colour);
    }
}

// Reads every element in header order. Truncation is found where the data ends (exact line or byte offset), so
// reservations are capped by what the body can hold: a header claiming millions of entries over a few bytes of body
// allocates only for those bytes. Every loop iteration consumes at least one token or byte, or throws.
template <class Reader>
void read_body(Reader& r, const Header& header, size_t body_size, MeshData& mesh) {
    uint64_t vertex_count = 0;
    for (const Element& e : header.elements)
        if (e.name == "vertex") vertex_count = e.count;
    for (const Element& e : header.elements) {
        const uint64_t min_bytes = std::max<uint64_t>(1, min_instance_bytes(e, header.format));
        const auto reserve = static_cast<size_t>(std::min<uint64_t>(e.count, (uint64_t{body_size} + 1) / min_bytes));
        if (e.name == "vertex")
            read_vertices(r, e, reserve, mesh);
        else if (e.name == "face")
            read_faces(r, e, vertex_count, reserve, mesh);
        else
            skip_element(r, e);
    }
    r.finish();
}

std::string object_name(const std::string& name) {
    std::string stem = std::filesystem::path(name).stem().string();
    return stem.empty() ? std::string("mesh") : stem;
}

}  // namespace

MeshData parse_ply(std::string_view bytes, const std::string& name) {
    const Header header = HeaderParser(bytes, name).parse();
    const std::string_view body = bytes.substr(header.body_offset);

    MeshData mesh;
    if (header.format == Format::Ascii) {
        AsciiReader reader(body, header.line_count + 1, name);
        read_body(reader, header, body.size(), mesh);
    } else {
        BinaryReader reader(body, header.body_offset, name);
        read_body(reader, header, body.size(), mesh);
    }
    mesh.object_names.push_back(object_name(name));
    mesh.object_first_triangle.push_back(0);
    return mesh;
}

MeshData load_ply(const std::filesystem::path& path) {
    const std::string name = path.string();
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) throw InputError(name, 0, 0, "cannot read PLY file: is a directory");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(name, 0, 0, std::string("cannot open PLY file: ") + std::strerror(errno));
    const uintmax_t size = std::filesystem::file_size(path, ec);
    if (!ec && size > kMaxFileBytes)
        throw InputError(name, 0, 0, "PLY file is too large: " + std::to_string(size) + " bytes (limit 2 GiB)");
    std::string bytes;
    if (!ec) bytes.reserve(static_cast<size_t>(size));
    constexpr size_t kChunk = size_t{1} << 20;
    std::vector<char> chunk(kChunk);
    for (;;) {
        in.read(chunk.data(), static_cast<std::streamsize>(kChunk));
        const auto got = static_cast<size_t>(in.gcount());
        if (bytes.size() + got > kMaxFileBytes)
            throw InputError(name, 0, 0, "PLY file is too large (limit 2 GiB)");
        bytes.append(chunk.data(), got);
        if (in.eof()) break;
        if (!in) throw InputError(name, 0, 0, "error while reading PLY file");
    }
    return parse_ply(bytes, name);
}

}  // namespace raster
