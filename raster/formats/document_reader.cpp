// Typed, located reads from a parsed scene document: numbers, booleans, strings, vectors and map keys.
#include "raster/formats/document_reader.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <vector>

#include "raster/core/errors.h"

namespace raster {
namespace {

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

void DocumentReader::fail(const Node& node, const std::string& message) const {
    throw InputError(file_, node.line(), node.column(), message);
}

const Node& DocumentReader::optional(const Node& map, const char* key) const {
    for (const Node::Entry& entry : map.entries())
        if (entry.key.is_scalar() && entry.key.text() == key) return entry.value;
    return Node::undefined();
}

const Node& DocumentReader::required(const Node& map, const char* key) const {
    const Node& value = optional(map, key);
    if (!value.is_defined()) fail(map, std::string("missing required key '") + key + "'");
    return value;
}

std::string DocumentReader::unknown_keys(const Node& map, std::initializer_list<const char*> allowed) const {
    std::string unknown;
    for (const Node::Entry& entry : map.entries()) {
        const std::string key = entry.key.is_scalar() ? entry.key.text() : "?";
        bool known = false;
        for (const char* name : allowed) known = known || key == name;
        if (!known) unknown += (unknown.empty() ? "'" : ", '") + key + "'";
    }
    return unknown;
}

void DocumentReader::check_keys(const Node& map, std::initializer_list<const char*> allowed) const {
    for (const Node::Entry& entry : map.entries()) {
        const std::string key = entry.key.is_scalar() ? entry.key.text() : "";
        if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) continue;
        // Only an unknown key pays for the edit distances of the suggestion.
        const char* closest = nullptr;
        size_t closest_distance = 3;  // suggest only near misses
        for (const char* name : allowed) {
            const size_t distance = edit_distance(key, name);
            if (distance < closest_distance) closest_distance = distance, closest = name;
        }
        std::string message = "unknown key '" + key + "'";
        if (closest) message += std::string(" (did you mean '") + closest + "'?)";
        else {
            message += "; expected one of";
            for (const char* name : allowed) message += std::string(" '") + name + "'";
        }
        fail(entry.key, message);
    }
}

void DocumentReader::expect_map(const Node& node, const char* what) const {
    if (!node.is_map()) fail(node, std::string(what) + " must be a map of keys to values");
}

void DocumentReader::expect_sequence(const Node& node, const char* what) const {
    if (!node.is_sequence()) fail(node, std::string(what) + " must be a list");
}

double DocumentReader::number(const Node& node, const char* what) const {
    if (!node.is_scalar()) fail(node, std::string(what) + " must be a number");
    const std::string& text = node.text();
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

float DocumentReader::finite_float(const Node& node, const char* what) const {
    const double value = number(node, what);
    if (std::fabs(value) > 3.0e38) fail(node, std::string(what) + " is too large for a float: " + node.text());
    return static_cast<float>(value);
}

int DocumentReader::integer(const Node& node, const char* what, int min, int max) const {
    const double value = number(node, what);
    if (value != std::floor(value)) fail(node, std::string(what) + " must be a whole number, got " + node.text());
    if (value < min || value > max)
        fail(node, std::string(what) + " must be in " + std::to_string(min) + ".." + std::to_string(max) + ", got " +
                       node.text());
    return static_cast<int>(value);
}

bool DocumentReader::boolean(const Node& node, const char* what) const {
    if (node.is_scalar()) {
        const std::string& text = node.text();
        if (text == "true" || text == "yes" || text == "on") return true;
        if (text == "false" || text == "no" || text == "off") return false;
    }
    fail(node, std::string(what) + " must be true or false");
}

std::string DocumentReader::string(const Node& node, const char* what) const {
    if (!node.is_scalar()) fail(node, std::string(what) + " must be a string");
    return node.text();
}

glm::vec3 DocumentReader::vec3(const Node& node, const char* what, bool scalar_ok) const {
    if (scalar_ok && node.is_scalar()) return glm::vec3(finite_float(node, what));
    if (!node.is_sequence() || node.size() != 3)
        fail(node, std::string(what) + (scalar_ok ? " must be a number or a list of 3 numbers"
                                                  : " must be a list of 3 numbers [x, y, z]"));
    return {finite_float(node[0], what), finite_float(node[1], what), finite_float(node[2], what)};
}

}  // namespace raster
