// The tiling check behind the coverage, watertightness and extreme-coverage properties: triangles drawn one at a
// time with the implementation, compared sample by sample with the exact-integer reference on snapped vertices.
#pragma once

#include "properties/generators.h"
#include "properties/implementation.h"

namespace raster::properties {

// Draws every triangle of the case alone and requires, for every sample of the frame:
//  - the number of triangles covering it equals the reference's (exact 128-bit orientation tests with the
//    top-left rule, which covers each sample of a valid tiling at most once);
//  - a sample exactly on an edge shared by two triangles, or on a vertex inside the union, is covered exactly once;
//  - when the union's outline is strictly convex, samples inside it (top-left rule) are covered once, others never.
// Classifies the case by kind and by whether samples lay exactly on shared edges and shared vertices.
void check_tiling(const Implementation& impl, const TilingCase& c);

// Which triangles cover each sample when drawn alone (bit t of the entry: triangle t; at most 32 triangles are
// tracked), for checks that need to know the owner rather than the count.
std::vector<uint32_t> coverage_owners(const Implementation& impl, const Frame& frame,
                                      const std::vector<ClipTriangle>& triangles);

}  // namespace raster::properties
