// Sampling: a triangle's N x N-grid coverage converges to its exact area within a perimeter bound, and the
// standard patterns are the documented positions.
#pragma once

#include "properties/implementation.h"

namespace raster::properties {

// With h = 1/N px the samples form a lattice of spacing h (offsets rounded to the fixed-point grid move each by
// at most 2^-(fixed_bits + 1) per coordinate, under h/2 for N <= 16, so each stays inside its own h-cell). Give
// each sample its h-cell: a cell away from the boundary counts exactly its area, so only cells meeting the
// boundary err, by at most h^2 each. A segment meets at most 3 + (|dx| + |dy|) / h cells, and |dx| + |dy| <=
// sqrt(2) length, so for the snapped triangle's area A and perimeter P (pixels):
//     |covered / N^2 - A| <= sqrt(2) P / N + 9 / N^2.
void check_grid_coverage_converges_to_the_exact_area_within_a_perimeter_bound(const Implementation& impl);

// The implementation's offsets for 1, 2, 4, 8 and 16 standard samples equal the documented tables exactly, and
// its N x N grids (N = 1 .. 16) equal ((i + 0.5) / N, (j + 0.5) / N) within one float rounding (2^-25). Every
// pattern is checked in every case: there are few enough to enumerate.
void check_standard_patterns_are_the_documented_positions(const Implementation& impl);

}  // namespace raster::properties
