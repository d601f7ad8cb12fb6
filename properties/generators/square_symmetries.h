// The symmetries of a square frame as signed permutation matrices, for placing meshes and for the fill-rule
// property's mirrors and quarter turns.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "properties/stage_driver.h"

namespace raster::properties {

// The linear part of a symmetry of the square frame (a signed permutation matrix, rows as {xx, xy, yx, yy}).
struct FrameSymmetry {
    std::string name;
    int m[4];
};
std::ostream& operator<<(std::ostream& os, const FrameSymmetry& g);

// The eight symmetries of the square (identity first).
const std::vector<FrameSymmetry>& all_symmetries();

// The seven non-identity mirrors and quarter turns.
const std::vector<FrameSymmetry>& square_symmetries();

// A screen point moved by the symmetry about the frame's centre.
glm::dvec2 apply(const FrameSymmetry& g, const Frame& frame, const glm::dvec2& screen);

}  // namespace raster::properties
