// Shared by the seed 001 tests: balboa's grey background, the document's projection to screen pixels, and colours.
#pragma once

#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace raster::seed_test {

inline constexpr uint8_t kGrey = 128;  // 0.5 * 255 = 127.5, rounded to nearest (half up)

inline std::vector<std::string> words(const std::string& line) {
    std::istringstream in(line);
    std::vector<std::string> out;
    for (std::string word; in >> word;) out.push_back(word);
    return out;
}

// Eq. (5) then eq. (2) and its y counterpart (y down): camera space to screen pixels.
inline glm::dvec2 to_screen(const glm::dvec3& p, double s, int width, int height) {
    const double a = double(width) / height;
    const double x = -p.x / p.z, y = -p.y / p.z;
    return {width * (x + s * a) / (2 * s * a), height * (s - y) / (2 * s)};
}

inline bool same_color(const uint8_t* pixel, const int expected[3], int tolerance) {
    for (int c = 0; c < 3; ++c)
        if (std::abs(int(pixel[c]) - expected[c]) > tolerance) return false;
    return true;
}

}  // namespace raster::seed_test
