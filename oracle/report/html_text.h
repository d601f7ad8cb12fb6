// Text for the report's pages: HTML escaping, and the comparison JSON's numbers as the pages print them (a field
// that is missing or mistyped prints as "-", never throws: a page may be given an older or hand-edited JSON).
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace raster::oracle {

// & < > " ' as entities.
std::string escape_html(const std::string& text);

// An integer as written, a float with one decimal.
std::string number(const nlohmann::json& value);

// A fraction as a percentage with four decimals; "-" when not a number.
std::string percent(const nlohmann::json& value);

// A number with `digits` decimals; "-" when not a number.
std::string fixed(const nlohmann::json& value, int digits);

// object[key], or null when it is missing or object is not an object.
nlohmann::json field(const nlohmann::json& object, const char* key);

// object[key] as text, or "" when it is missing or not a string.
std::string text(const nlohmann::json& object, const char* key);

// The elements of object[key] that are objects (none when it is missing or not an array).
std::vector<nlohmann::json> objects(const nlohmann::json& object, const char* key);

}  // namespace raster::oracle
