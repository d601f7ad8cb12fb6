// Typed, located reads from YAML/JSON documents, with a strict JSON pre-check and a nesting limit.
#include "raster/formats/yaml_reader.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include <nlohmann/json.hpp>
#include <yaml-cpp/depthguard.h>

#include "raster/core/errors.h"

namespace raster {
namespace {

constexpr int kMaxNesting = 64;

int line_of(const YAML::Node& node) { return node.Mark().line >= 0 ? node.Mark().line + 1 : 0; }
int column_of(const YAML::Node& node) { return node.Mark().column >= 0 ? node.Mark().column + 1 : 0; }

// Flow nesting ([ and {) outside quoted strings; yaml-cpp recurses once per level.
void check_nesting(std::string_view text, const std::string& file) {
    int depth = 0, line = 1;
    char quote = 0;
    for (size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (c == '\n') ++line;
        if (quote) {
            if (c == '\\' && quote == '"') ++i;
            else if (c == quote) quote = 0;
            continue;
        }
        if (c == '"' || c == '\'') quote = c;
        else if (c == '#' && (i == 0 || text[i - 1] == ' ' || text[i - 1] == '\n'))
            while (i + 1 < text.size() && text[i + 1] != '\n') ++i;
        else if (c == '[' || c == '{') {
            if (++depth > kMaxNesting)
                throw InputError(file, line, 0, "nesting deeper than " + std::to_string(kMaxNesting) + " levels");
        } else if (c == ']' || c == '}') {
            depth = std::max(0, depth - 1);
        }
    }
}

// Accepts every JSON event without building a document: only the syntax check is wanted.
struct SyntaxOnly : nlohmann::json_sax<nlohmann::json> {
    bool null() override { return true; }
    bool boolean(bool) override { return true; }
    bool number_integer(number_integer_t) override { return true; }
    bool number_unsigned(number_unsigned_t) override { return true; }
    bool number_float(number_float_t, const string_t&) override { return true; }
    bool string(string_t&) override { return true; }
    bool binary(binary_t&) override { return true; }
    bool start_object(std::size_t) override { return true; }
    bool key(string_t&) override { return true; }
    bool end_object() override { return true; }
    bool start_array(std::size_t) override { return true; }
    bool end_array() override { return true; }
    bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception& e) override {
        throw nlohmann::json::parse_error::create(101, 0, e.what(), nullptr);
    }
};

// nlohmann's parse_error text: "[json.exception.parse_error.101] parse error at line 3, column 5: ...".
void check_json_syntax(std::string_view text, const std::string& file) {
    try {
        SyntaxOnly sax;
        nlohmann::json::sax_parse(text.begin(), text.end(), &sax);
    } catch (const nlohmann::json::parse_error& e) {
        const std::string what = e.what();
        int line = 0, column = 0;
        std::string problem = what;
        // "... parse error at line 3, column 5: <problem>": the location goes into InputError, the rest is the problem.
        const size_t at = what.find("line ");
        int consumed = 0;
        if (at != std::string::npos &&
            std::sscanf(what.c_str() + at, "line %d, column %d: %n", &line, &column, &consumed) == 2 && consumed > 0)
            problem = what.substr(at + static_cast<size_t>(consumed));
        throw InputError(file, line, column, "JSON syntax error: " + problem);
    }
}

size_t edit_distance(const std::string& a, const std::string& b) {
    std::vector<size_t> row(b.size() + 1);
    for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (size_t i = 1; i <= a.size(); ++i) {
        size_t diagonal = row[0];
        row[0] = i;
        for (size_t j = 1; j <= b.size(); ++j) {
            const size_t above = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] != b[j - 1])});
            diagonal = above;
        }
    }
    return row[b.size()];
}

}  // namespace

YAML::Node parse_document(std::string_view text, const std::string& file) {
    check_nesting(text, file);
    const size_t first = text.find_first_not_of(" \t\r\n");
    if (first != std::string_view::npos && (text[first] == '{' || text[first] == '['))
        check_json_syntax(text, file);
    try {
        return YAML::Load(std::string(text));
    } catch (const YAML::DeepRecursion& e) {  // block nesting, which check_nesting does not count
        throw InputError(file, e.mark.line >= 0 ? e.mark.line + 1 : 0, e.mark.column >= 0 ? e.mark.column + 1 : 0,
                         "nesting deeper than " + std::to_string(kMaxNesting) + " levels");
    } catch (const YAML::Exception& e) {
        throw InputError(file, e.mark.line >= 0 ? e.mark.line + 1 : 0, e.mark.column >= 0 ? e.mark.column + 1 : 0,
                         "YAML syntax error: " + e.msg);
    }
}

void YamlReader::fail(const YAML::Node& node, const std::string& message) const {
    throw InputError(file_, line_of(node), column_of(node), message);
}

YAML::Node YamlReader::optional(const YAML::Node& map, const char* key) const {
    for (const auto& entry : map)
        if (entry.first.IsScalar() && entry.first.Scalar() == key) return entry.second;
    return YAML::Node(YAML::NodeType::Undefined);
}

YAML::Node YamlReader::required(const YAML::Node& map, const char* key) const {
    YAML::Node value = optional(map, key);
    if (!value.IsDefined()) fail(map, std::string("missing required key '") + key + "'");
    return value;
}

std::string YamlReader::unknown_keys(const YAML::Node& map, std::initializer_list<const char*> allowed) const {
    std::string unknown;
    for (const auto& entry : map) {
        const std::string key = entry.first.IsScalar() ? entry.first.Scalar() : "?";
        bool known = false;
        for (const char* name : allowed) known = known || key == name;
        if (!known) unknown += (unknown.empty() ? "'" : ", '") + key + "'";
    }
    return unknown;
}

void YamlReader::check_keys(const YAML::Node& map, std::initializer_list<const char*> allowed) const {
    for (const auto& entry : map) {
        const std::string key = entry.first.IsScalar() ? entry.first.Scalar() : "";
        bool known = false;
        const char* closest = nullptr;
        size_t closest_distance = 3;  // suggest only near misses
        for (const char* name : allowed) {
            if (key == name) known = true;
            const size_t distance = edit_distance(key, name);
            if (distance < closest_distance) closest_distance = distance, closest = name;
        }
        if (known) continue;
        std::string message = "unknown key '" + key + "'";
        if (closest) message += std::string(" (did you mean '") + closest + "'?)";
        else {
            message += "; expected one of";
            for (const char* name : allowed) message += std::string(" '") + name + "'";
        }
        fail(entry.first, message);
    }
}

void YamlReader::expect_map(const YAML::Node& node, const char* what) const {
    if (!node.IsMap()) fail(node, std::string(what) + " must be a map of keys to values");
}

void YamlReader::expect_sequence(const YAML::Node& node, const char* what) const {
    if (!node.IsSequence()) fail(node, std::string(what) + " must be a list");
}

double YamlReader::number(const YAML::Node& node, const char* what) const {
    if (!node.IsScalar()) fail(node, std::string(what) + " must be a number");
    const std::string& text = node.Scalar();
    std::string lowered;
    for (char c : text) lowered += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (lowered == ".nan" || lowered == ".inf" || lowered == "-.inf" || lowered == "+.inf" || lowered == "nan" ||
        lowered == "inf" || lowered == "-inf" || lowered == "infinity" || lowered == "-infinity")
        fail(node, std::string(what) + " must be a finite number, got '" + text + "'");
    errno = 0;
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    if (text.empty() || end != text.c_str() + text.size())
        fail(node, std::string(what) + " must be a number, got '" + text + "'");
    if (!std::isfinite(value)) fail(node, std::string(what) + " is out of range: '" + text + "'");
    return value;
}

float YamlReader::finite_float(const YAML::Node& node, const char* what) const {
    const double value = number(node, what);
    if (std::fabs(value) > 3.0e38) fail(node, std::string(what) + " is too large for a float: " + node.Scalar());
    return static_cast<float>(value);
}

int YamlReader::integer(const YAML::Node& node, const char* what, int min, int max) const {
    const double value = number(node, what);
    if (value != std::floor(value)) fail(node, std::string(what) + " must be a whole number, got " + node.Scalar());
    if (value < min || value > max)
        fail(node, std::string(what) + " must be in " + std::to_string(min) + ".." + std::to_string(max) + ", got " +
                       node.Scalar());
    return static_cast<int>(value);
}

bool YamlReader::boolean(const YAML::Node& node, const char* what) const {
    if (node.IsScalar()) {
        const std::string& text = node.Scalar();
        if (text == "true" || text == "yes" || text == "on") return true;
        if (text == "false" || text == "no" || text == "off") return false;
    }
    fail(node, std::string(what) + " must be true or false");
}

std::string YamlReader::string(const YAML::Node& node, const char* what) const {
    if (!node.IsScalar()) fail(node, std::string(what) + " must be a string");
    return node.Scalar();
}

glm::vec3 YamlReader::vec3(const YAML::Node& node, const char* what, bool scalar_ok) const {
    if (scalar_ok && node.IsScalar()) return glm::vec3(finite_float(node, what));
    if (!node.IsSequence() || node.size() != 3)
        fail(node, std::string(what) + (scalar_ok ? " must be a number or a list of 3 numbers"
                                                  : " must be a list of 3 numbers [x, y, z]"));
    return {finite_float(node[0], what), finite_float(node[1], what), finite_float(node[2], what)};
}

}  // namespace raster
