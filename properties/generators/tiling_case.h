// A tiling case: a triangulated region in screen space on a frame, the input of the tiling check and the fill-rule
// and sampling properties.
#pragma once

#include <array>
#include <ostream>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "properties/reference/coverage_reference.h"
#include "properties/stage_driver.h"

namespace raster::properties {

// A triangulated region in screen space. Vertices are on the frame's exact grid, so they land exactly where they
// are put; w is each vertex's view depth (a power of two, so the vertex stays exact under perspective).
struct ScreenMesh {
    std::vector<glm::dvec2> vertices;
    std::vector<float> w;
    std::vector<std::array<int, 3>> triangles;  // drawing order and winding as generated
    std::vector<int> outline;                   // the union's boundary when it is strictly convex, else empty
    std::vector<int> interior;                  // vertices inside the union (every way out crosses a triangle)
};

struct TilingCase {
    std::string kind;
    Frame frame;
    ScreenMesh mesh;
};
std::ostream& operator<<(std::ostream& os, const TilingCase& c);

// The mesh's triangles in clip space (depth 0.5, each vertex at its own w).
std::vector<ClipTriangle> clip_triangles(const Frame& frame, const ScreenMesh& mesh);

// The mesh's vertices where setup puts them: through clip space, the divide, the viewport and snapping.
std::vector<reference::Point> snapped_vertices(const Frame& frame, const ScreenMesh& mesh);

}  // namespace raster::properties
