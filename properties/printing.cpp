// Exact literals: nine significant digits for floats and seventeen for doubles read back unchanged.
#include "properties/printing.h"

#include <cmath>
#include <cstdio>

namespace raster::properties {
namespace {

std::string non_finite(double value) {
    if (std::isnan(value)) return std::signbit(value) ? "-NAN" : "NAN";
    return value > 0 ? "INFINITY" : "-INFINITY";
}

}  // namespace

std::string float_literal(float value) {
    if (!std::isfinite(value)) return non_finite(value);
    char text[40];
    std::snprintf(text, sizeof text, "%.9gf", static_cast<double>(value));
    std::string s = text;
    if (s.find_first_of(".e") == std::string::npos) s.insert(s.size() - 1, ".0");  // "3f" is not a literal
    return s;
}

std::string double_literal(double value) {
    if (!std::isfinite(value)) return non_finite(value);
    char text[40];
    std::snprintf(text, sizeof text, "%.17g", value);
    std::string s = text;
    if (s.find_first_of(".e") == std::string::npos) s += ".0";
    return s;
}

std::string literal(const glm::vec3& v) {
    return "glm::vec3(" + float_literal(v.x) + ", " + float_literal(v.y) + ", " + float_literal(v.z) + ")";
}

std::string literal(const glm::vec4& v) {
    return "glm::vec4(" + float_literal(v.x) + ", " + float_literal(v.y) + ", " + float_literal(v.z) + ", " +
           float_literal(v.w) + ")";
}

std::string literal(const glm::dvec2& v) {
    return "glm::dvec2(" + double_literal(v.x) + ", " + double_literal(v.y) + ")";
}

}  // namespace raster::properties
