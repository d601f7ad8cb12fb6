// The raster target's invariants: a rendered visibility buffer against what the exact reference (reference_frame.h)
// says each sample shows, each invariant with the precision modes it holds for. A failure prints the sample, both
// sides' view of it and the scene, then traps (fuzz_check.h).
#pragma once

#include <cstdint>

#include "fuzz/reference_frame.h"
#include "raster/rasterize/visibility_buffer.h"
#include "raster/scene/scene.h"

namespace raster::fuzz {

// Every sample of the frame, in every mode (snap bits, edges, interpolation, depth format, clipping, hierarchical
// Z, culling), wherever the reference can decide:
//  1. coverage: a sample some piece certainly covers is not empty, and a non-empty sample shows a triangle that
//     covers it. Undecided (maybe): with float edges, samples within the float edge error of an edge; with
//     culling, every sample of a triangle whose facing is within float error of edge-on;
//  2. depth: the triangle shown is the nearest that covers the sample, ties to the earlier: no triangle certainly
//     covering it has a depth key certainly larger than the one shown, nor one at least as large and drawn
//     earlier. Undecided where the key intervals (raster's rounding in the scene's depth format) overlap;
//  3. ties keep the earlier: a triangle whose clip-space vertices are bit-identical to an earlier one's (so its
//     keys are too) is never shown;
//  4. interpolation (fixed-point edges only): where the triangle shown certainly covers the sample, its
//     barycentrics and view depth are within raster's derived float error of the exact interpolation on the
//     snapped piece, perspective-correct or affine as the scene says. Float edges do not bound it: raster divides
//     its float edge values by the exact area, so the weights drift by the edge error over the area, without
//     limit for a small triangle at large coordinates.
void check_visibility(const ReferenceFrame& reference, const VisibilityBuffer& buffer, const Scene& scene);

// Triangles [first, end) are a closed fan around their shared first vertex, each drawn unclipped as one piece,
// well conditioned (snapping cannot fold it) and with fixed-point edges (float edges may crack or double a shared
// edge by design, precision_modes.h): every sample strictly inside the fan's rim is covered by exactly one fan
// triangle under the reference's top-left rule and is not empty in the buffer, and no sample is covered twice.
// The caller decides that the fan is checkable.
void check_fan(const ReferenceFrame& reference, const VisibilityBuffer& buffer, uint32_t first, uint32_t end,
               const Scene& scene);

}  // namespace raster::fuzz
