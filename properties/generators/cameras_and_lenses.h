// The camera and lens generators for the matrix and depth properties.
#pragma once

#include <ostream>
#include <string>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <rapidcheck.h>

namespace raster::properties {

struct CameraCase {
    std::string kind;
    glm::vec3 eye, target, up;
};
std::ostream& operator<<(std::ostream& os, const CameraCase& c);
rc::Gen<CameraCase> cameras();  // random, far from the origin, very close target, up nearly parallel, long up

struct LensCase {
    std::string kind;
    float fov_y_degrees = 45.0f, aspect = 1.0f, near = 0.1f, far = 100.0f;
    int width = 640, height = 480;  // an image with this aspect (approximately, for the border checks)
    float depth = 1.0f;             // a view depth in [near, far]
    float farther = 2.0f;           // a second one, > depth * (1 + 2^-19), in (depth, far]
    glm::vec2 across{0.0f};         // a point of the frustum's cross-section, in [-1, 1]^2
};
std::ostream& operator<<(std::ostream& os, const LensCase& c);
rc::Gen<LensCase> lenses();  // random, near = 1e-6 and far = 1e9, far = near (1 + 2^-10), fov 1 and 179 degrees

}  // namespace raster::properties
