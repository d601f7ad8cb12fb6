// The generators of whole scenes at the extremes: two quads over near = 1e-6 to far = 1e9, and a triangle scaled
// towards the float limits.
#pragma once

#include <array>
#include <ostream>
#include <string>

#include <glm/vec3.hpp>
#include <rapidcheck.h>

namespace raster::properties {

struct DepthPairCase {
    std::string kind;
    float near_depth, far_depth;  // two fronto-parallel quads, near_depth < far_depth, over near = 1e-6, far = 1e9
    bool nearer_first;
};
std::ostream& operator<<(std::ostream& os, const DepthPairCase& c);
rc::Gen<DepthPairCase> depth_pairs_over_extreme_range();

struct ScaledSceneCase {
    std::string kind;
    int exponent;                         // the scene is scaled by 2^exponent
    std::array<glm::vec3, 3> triangle;    // world space, in front of the camera
    glm::vec3 eye, target;
    float near, far;
};
std::ostream& operator<<(std::ostream& os, const ScaledSceneCase& c);
rc::Gen<ScaledSceneCase> scenes_scaled_towards_float_limits();

}  // namespace raster::properties
