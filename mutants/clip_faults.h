// The clip stage's faulty variants of the bug catalogue, each with the real clip_triangle's signature (that of
// PipelineStages::clip); clip_faults.cpp describes each bug where it is written.
#pragma once

#include "raster/pipeline/clip.h"

namespace raster::mutants {

using ClipStage = decltype(clip_triangle);

ClipStage clip_without_near;            // "no near clipping"
ClipStage clip_dropping_near_crossers;  // "w <= 0 dropped instead of clipped"
ClipStage clip_without_side_planes;     // "side planes not clipped (vertices clamped instead)"
ClipStage clip_with_strict_near_far;    // "near and far tested with a strict inequality"
ClipStage clip_letting_nan_through;     // "NaN slips through the clip test"

}  // namespace raster::mutants
