// Typed, located reads from a parsed scene document (YAML or JSON): every error names the file, line and column.
#pragma once

#include <initializer_list>
#include <string>

#include <glm/vec3.hpp>

#include "raster/formats/document.h"

namespace raster {

// Reads values out of a parsed document. Every failure throws InputError with the node's line and column.
class DocumentReader {
public:
    explicit DocumentReader(std::string file) : file_(std::move(file)) {}

    const std::string& file() const { return file_; }

    [[noreturn]] void fail(const Node& node, const std::string& message) const;

    // `key` of map `node`, or Node::undefined() when absent.
    const Node& optional(const Node& map, const char* key) const;
    const Node& required(const Node& map, const char* key) const;
    // Rejects keys not in `allowed` (catching typos such as "fow"), naming the closest allowed key.
    void check_keys(const Node& map, std::initializer_list<const char*> allowed) const;
    // Lists the keys not in `allowed`, for formats that only warn about them.
    std::string unknown_keys(const Node& map, std::initializer_list<const char*> allowed) const;

    void expect_map(const Node& node, const char* what) const;
    void expect_sequence(const Node& node, const char* what) const;

    // Ints and floats are both numbers; finite unless allow_non_finite.
    double number(const Node& node, const char* what) const;
    float finite_float(const Node& node, const char* what) const;
    int integer(const Node& node, const char* what, int min, int max) const;
    bool boolean(const Node& node, const char* what) const;
    std::string string(const Node& node, const char* what) const;
    // A 3-vector [x, y, z]; with `scalar_ok`, a single number n also reads as [n, n, n].
    glm::vec3 vec3(const Node& node, const char* what, bool scalar_ok = false) const;

private:
    std::string file_;
};

}  // namespace raster
