// The depth image check: the greyscale image raster writes of a frame's depth (`--depth-out`, seed 000's
// shading-depth task; docs/cli.md), worked out again here from its written definition over raster's own per-sample
// view depths (which the sample classifier judges against the oracle's), and compared with the file's pixels.
#pragma once

#include <cstdint>
#include <vector>

#include "oracle/compare/raster_output.h"

namespace raster::oracle {

// The definition: per pixel the nearest covered sample's view depth d; with lo and hi the nearest and farthest such
// depth in the image, the byte is 255 - 223 (d - lo) / (hi - lo) (hi - lo taken as 1 when they are equal), rounded
// half up; a pixel no sample covers is 0. raster works it out in float: its error is below kDepthByteSlack of a
// byte (a few float roundings of values at most 255), so a byte is allowed when it rounds a value within that of
// the exact one.
inline constexpr double kDepthByteSlack = 0x1p-12;

struct DepthImageCheck {
    uint64_t pixels = 0;       // judged: every pixel of the image
    uint64_t genuine = 0;      // pixels outside their allowed bytes (or a file of the wrong size: every pixel)
    int max_difference = 0;    // largest distance of a pixel's byte from its allowed ones
    std::vector<uint8_t> genuine_pixels;  // per pixel
    struct Disagreement {
        int x = 0, y = 0, file = 0, lo = 0, hi = 0;  // the byte read and the bytes allowed
    };
    std::vector<Disagreement> first;  // the first few, row by row
};

// Checks the decoded depth file `image` (one grey channel, or the first channel of a wider one) against the
// definition over `samples`.
DepthImageCheck check_depth_image(const RasterSamples& samples, const RasterPixels& image);

}  // namespace raster::oracle
