// The clip-space generators: one triangle in clip space on a frame with a clip volume, inside, on the planes,
// across them, far off screen, with w near zero, or with non-finite coordinates.
#pragma once

#include <ostream>
#include <string>

#include <rapidcheck.h>

#include "properties/stage_driver.h"

namespace raster::properties {

// One triangle in clip space on a frame with a clip volume.
struct ClipCase {
    std::string kind;
    Frame frame;
    ClipTriangle triangle;
};
std::ostream& operator<<(std::ostream& os, const ClipCase& c);

rc::Gen<ClipCase> perspective_triangles_inside();   // inside the frustum, vertices at different view depths
rc::Gen<ClipCase> triangles_inside_the_volume();    // inside or exactly on its planes (near, far, sides)
rc::Gen<ClipCase> triangles_crossing_the_volume();  // behind the eye, across near/far/sides, far off screen, w ~ 0
rc::Gen<ClipCase> triangles_far_off_screen();       // vertices up to 2^20 pixels off screen
rc::Gen<ClipCase> triangles_with_w_near_zero();     // a vertex with w = 0, +-denormal, +-1e-30, +-near * 1e-7
rc::Gen<ClipCase> triangles_with_non_finite_coordinates();  // NaN or +-Inf in one to three coordinates

}  // namespace raster::properties
