// The symmetries of the square frame: the eight signed permutations and how they move a screen point.
#include "properties/generators/square_symmetries.h"

namespace raster::properties {

const std::vector<FrameSymmetry>& all_symmetries() {
    static const std::vector<FrameSymmetry> list = {
        {"identity", {1, 0, 0, 1}},        {"mirror x", {-1, 0, 0, 1}},      {"mirror y", {1, 0, 0, -1}},
        {"half turn", {-1, 0, 0, -1}},     {"quarter turn", {0, -1, 1, 0}},  {"three-quarter turn", {0, 1, -1, 0}},
        {"transpose", {0, 1, 1, 0}},       {"anti-transpose", {0, -1, -1, 0}}};
    return list;
}

std::ostream& operator<<(std::ostream& os, const FrameSymmetry& g) { return os << g.name; }

const std::vector<FrameSymmetry>& square_symmetries() {
    static const std::vector<FrameSymmetry> list(all_symmetries().begin() + 1, all_symmetries().end());
    return list;
}

glm::dvec2 apply(const FrameSymmetry& g, const Frame& frame, const glm::dvec2& p) {
    const double cx = 0.5 * frame.width, cy = 0.5 * frame.height;
    const double dx = p.x - cx, dy = p.y - cy;
    return {g.m[0] * dx + g.m[1] * dy + cx, g.m[2] * dx + g.m[3] * dy + cy};
}

}  // namespace raster::properties
