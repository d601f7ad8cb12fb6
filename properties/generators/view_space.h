// The view-space generators: triangles in view space (camera at the origin looking down -z), seen through a
// 90 degree lens, for the depth properties and the near-plane extreme.
#pragma once

#include <array>
#include <ostream>
#include <string>
#include <vector>

#include <glm/vec3.hpp>
#include <rapidcheck.h>

#include "properties/stage_driver.h"

namespace raster::properties {

// Triangles in view space (camera at the origin looking down -z), seen through a 90 degree lens.
struct ViewTriangle {
    std::array<glm::vec3, 3> v;
};
struct LayeredCase {
    std::string kind;
    Frame frame;
    std::vector<ViewTriangle> triangles;
    std::vector<int> order;  // a permutation of the triangles, for draw-order checks
};
std::ostream& operator<<(std::ostream& os, const LayeredCase& c);

rc::Gen<LayeredCase> overlapping_triangles();      // at distinct depths, tilted, or intersecting each other
rc::Gen<LayeredCase> fronto_parallel_layers();     // each triangle at its own power-of-two depth: no ties anywhere
rc::Gen<LayeredCase> triangles_touching_the_near_plane();  // one triangle, one to three vertices exactly at w = near

}  // namespace raster::properties
