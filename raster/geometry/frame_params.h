// The frame's parameters for setup and both rasterizers, built once per frame: image size, fixed-point precision,
// clip volume, precision modes and the sample positions in float and on the fixed-point grid.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>

#include "raster/core/conventions.h"
#include "raster/geometry/clip.h"
#include "raster/geometry/sample_pattern.h"
#include "raster/scene/precision_modes.h"
#include "raster/scene/scene.h"

namespace raster {

// The extreme sample offsets inside a pixel, on the fixed-point grid: every sample of pixel (x, y) lies in
// [x << F + min_x, x << F + max_x] x [y << F + min_y, y << F + max_y].
struct SampleExtent {
    int64_t min_x = 0, max_x = 0, min_y = 0, max_y = 0;
};

struct FrameParams {
    int width = 0;
    int height = 0;
    int snap_bits = kDefaultSnapBits;                    // vertices snap to 1/2^snap_bits pixel
    int fixed_bits = fixed_bits_for(kDefaultSnapBits);   // samples and edge functions live on 1/2^fixed_bits
    ClipVolume clip;                                     // near, far and the side factor (full or guard band)
    EdgeArithmetic edges = EdgeArithmetic::fixed;
    Interpolation interpolation = Interpolation::perspective;
    DepthFormat depth = DepthFormat::reversed_z;
    bool hierarchical_z = true;                          // the tiled renderer's per-block depth bound
    std::vector<glm::vec2> sample_offsets;               // from the pixel's upper-left corner, pattern order
    FixedSampleOffsets fixed_offsets;                    // the same on the fixed-point grid
    SampleExtent extent;                                 // their extremes
    int threads = 0;                                     // 0 = all cores; results do not depend on it

    int samples() const { return static_cast<int>(sample_offsets.size()); }
};

// The frame a scene asks for, with these sample offsets (the sample_offsets stage's, so a test can plant wrong
// positions) and this thread count.
FrameParams frame_params_for(const Scene& scene, std::vector<glm::vec2> sample_offsets, int threads);

// A hand-made frame for stage tests: width x height pixels at snap_bits, full clipping with the default camera's
// near and far planes, the accurate modes, and these sample offsets (one sample at the pixel centre by default).
FrameParams frame_params(int width, int height, int snap_bits,
                         std::vector<glm::vec2> sample_offsets = {glm::vec2(0.5f, 0.5f)});

}  // namespace raster
