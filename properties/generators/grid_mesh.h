// Meshes on the integer grid of a frame (units of 2^-bits pixel), the screen-space generators' building blocks:
// boxes and regions of the frame, convex hulls, random windings and placements, documented samples as grid points,
// pairs sharing an edge through samples, and the kinds of single triangle.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <rapidcheck.h>

#include "properties/generators/frames.h"
#include "properties/generators/tiling_case.h"
#include "properties/reference/coverage_reference.h"

namespace raster::properties {

struct Box {
    int64_t x0, y0, x1, y1;  // inclusive, in grid units
};

// The whole frame as a box.
Box frame_box(const Frame& frame, int bits);

// A box inside the frame: the whole frame, a few pixels, or a few grid units.
struct Region {
    std::string name;
    Box box;
};
rc::Gen<Region> regions(const Frame& frame, int bits);

// A grid point uniform in the box.
reference::Point point_in(const Box& box);

// A triangulated region on the integer grid (units of 2^-bits pixel).
struct GridMesh {
    std::vector<reference::Point> vertices;
    std::vector<std::array<int, 3>> triangles;
    std::vector<int> outline, interior;
};

// Strictly convex hull (Andrew's monotone chain, collinear points dropped), counter-clockwise in y-up terms.
std::vector<reference::Point> convex_hull(std::vector<reference::Point> points);

// Each triangle's winding flipped at random (setup must handle both).
void random_windings(GridMesh& mesh);

// Puts the mesh in a random orientation (any symmetry of a square frame; mirrors and the half turn otherwise)
// and shifts it by up to a pixel, staying inside the frame.
void place(GridMesh& mesh, const Frame& frame, int bits);

// The grid mesh as a tiling case in pixels, with view depths all at w = 1 or each at its own power of two (the
// kind then says "in perspective").
TilingCase tiling_case(std::string kind, const Frame& frame, int bits, const GridMesh& grid);

// A documented sample position of pixel (x, y), in grid units (the frame must be sample-aligned).
reference::Point sample_point(const Frame& frame, int bits, int x, int y, int s);

// A random sample of the frame at least `margin` pixels from its border (where the frame allows), in grid units.
reference::Point random_sample_point(const Frame& frame, int bits, int margin);

// A pair sharing an edge that runs from one sample through further samples of the same index.
TilingCase pair_through_samples(const Frame& frame);

// One triangle of the given kind, in grid units.
GridMesh one_triangle(reference::Point a, reference::Point b, reference::Point c);

// A single triangle of a named kind (random in a region, axis-aligned, sliver, tiny, on pixel centres, off the
// snap grid) on the frame, with the grid bits its vertices are on.
struct NamedMesh {
    std::string name;
    GridMesh mesh;
    int bits;
};
rc::Gen<NamedMesh> single_triangle_meshes(const Frame& frame);

}  // namespace raster::properties
