// The frames the generators draw on (sample patterns, sizes, snap precisions, clip volumes), and the points and
// view depths they draw inside one, for the generator sources.
#pragma once

#include <glm/vec2.hpp>
#include <rapidcheck.h>

#include "properties/stage_driver.h"

namespace raster::properties {

struct SampleChoice {
    int samples;
    SamplePattern pattern;
};

// A frame of the given size, samples and snap precision, with the default clip volume.
Frame frame_of(int width, int height, SampleChoice choice, int snap_bits);

// Small square frames at the default precision, coarse and fine snapping, and extents at the limit of the
// fixed-point range: 16384 pixels along one side at 16 sub-pixel bits is 2^30 fixed-point units (conventions.h).
rc::Gen<Frame> coverage_frames();

// Bits of the grid vertices are placed on: the snap grid, unless floats cannot hold it exactly.
int position_bits(const Frame& frame);

// Coverage frames whose documented sample positions lie on their position grid (so a vertex can be put on a
// sample).
rc::Gen<Frame> sample_aligned_frames();

// Square frames whose sample pattern maps onto itself under mirrors and quarter turns: one sample at the pixel
// centre, or an N x N grid at 8 or more bits (no offset rounds half-way, so the rounded grid stays symmetric).
rc::Gen<Frame> symmetric_frames();

// View depths for clip tests: log-uniform over the volume (capped at 1e4 times near, where near is tiny).
float depth_in(const ClipVolume& v);

// A screen point at least `margin` pixels inside the frame's border.
glm::dvec2 screen_point_inside(const Frame& frame, double margin);

}  // namespace raster::properties
