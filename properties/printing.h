// How generated values print in RapidCheck's counterexamples: as C++ initialisers with exact numbers, so that a
// shrunk counterexample can be pasted into regressions_test.cpp as it is.
#pragma once

#include <ostream>
#include <string>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace raster::properties {

// A float literal that reads back to the same float ("0.100000001f", "INFINITY", "-NAN").
std::string float_literal(float value);
// A double literal that reads back to the same double.
std::string double_literal(double value);

std::string literal(const glm::vec3& v);   // glm::vec3(x, y, z) with float literals
std::string literal(const glm::vec4& v);   // glm::vec4(x, y, z, w)
std::string literal(const glm::dvec2& v);  // glm::dvec2(x, y) with double literals

}  // namespace raster::properties
