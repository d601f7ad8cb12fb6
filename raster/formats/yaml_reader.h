// Typed, located reads from a YAML (or JSON) document: every error names the file, line and column.
#pragma once

#include <filesystem>
#include <initializer_list>
#include <string>
#include <string_view>

#include <glm/vec3.hpp>
#include <yaml-cpp/yaml.h>

namespace raster {

// Parses text as YAML 1.2 (which also reads the JSON scene formats). JSON-looking text (starting with '{' or
// '[') is first checked by a strict JSON parser, whose syntax errors carry exact line and column. Nesting deeper
// than 64 levels is refused before parsing. Throws InputError naming `file`.
YAML::Node parse_document(std::string_view text, const std::string& file);

// Reads values out of a parsed document. Every failure throws InputError with the node's line and column.
class YamlReader {
public:
    explicit YamlReader(std::string file) : file_(std::move(file)) {}

    const std::string& file() const { return file_; }

    [[noreturn]] void fail(const YAML::Node& node, const std::string& message) const;

    // `key` of map `node`, or an undefined node when absent.
    YAML::Node optional(const YAML::Node& map, const char* key) const;
    YAML::Node required(const YAML::Node& map, const char* key) const;
    // Rejects keys not in `allowed` (catching typos such as "fow"), naming the closest allowed key.
    void check_keys(const YAML::Node& map, std::initializer_list<const char*> allowed) const;
    // Lists the keys not in `allowed`, for formats that only warn about them.
    std::string unknown_keys(const YAML::Node& map, std::initializer_list<const char*> allowed) const;

    void expect_map(const YAML::Node& node, const char* what) const;
    void expect_sequence(const YAML::Node& node, const char* what) const;

    // Ints and floats are both numbers; finite unless allow_non_finite.
    double number(const YAML::Node& node, const char* what) const;
    float finite_float(const YAML::Node& node, const char* what) const;
    int integer(const YAML::Node& node, const char* what, int min, int max) const;
    bool boolean(const YAML::Node& node, const char* what) const;
    std::string string(const YAML::Node& node, const char* what) const;
    // A 3-vector [x, y, z]; with `scalar_ok`, a single number n also reads as [n, n, n].
    glm::vec3 vec3(const YAML::Node& node, const char* what, bool scalar_ok = false) const;

private:
    std::string file_;
};

}  // namespace raster
