// The setup stage's faulty variants of the bug catalogue, each with the real setup_polygon's signature (that of
// PipelineStages::setup), and the culling test's, with faces_front's; setup_faults.cpp describes each bug where it
// is written.
#pragma once

#include "raster/pipeline/setup.h"

namespace raster::mutants {

using SetupStage = decltype(setup_polygon);

SetupStage setup_without_fill_rule;       // "no fill rule"
SetupStage setup_with_cracks;             // "cracks on shared edges"
SetupStage setup_with_float_edges;        // "float edge functions"
SetupStage setup_with_bottom_right_rule;  // "fill rule inverted (bottom-right)"
SetupStage setup_discarding_sub_pixel;    // "sub-pixel triangles discarded"
SetupStage setup_without_y_flip;          // "y not flipped"

decltype(faces_front) faces_front_inverted;  // "front faces culled (winding inverted)"

}  // namespace raster::mutants
