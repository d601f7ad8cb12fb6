// The last step of a frame rendered at a reduced internal resolution (RenderSettings::resolution_divisor): the
// internal image stretched bilinearly to the output size, in exact integer arithmetic.
//
// The convention (docs/conventions.md "Reduced resolution"): with divisor d, output pixel x has its centre at
// internal coordinate u = (x + 1/2) / d - 1/2. It blends internal pixels floor(u) and floor(u) + 1, each clamped
// to the image, with weights 1 - frac(u) and frac(u); rows the same with v; each channel's blend is rounded half
// up to a byte. For d = 2 and 4 every weight is a multiple of 1/(2d), so the blend is exact.
#pragma once

#include <cstdint>
#include <vector>

#include "raster/image/image.h"

namespace raster {

// Stretches `internal` to `out` (divisor times its width and height, the same channels) by the convention above,
// on `threads` threads (0: all cores); `rows` is scratch that a renderer keeps from frame to frame (each worker
// thread also keeps a row's phases). `divisor` is 2 or 4; 1 copies. Images of 1 to 4 channels, each blended on its
// own (so straight alpha is not premultiplied: raster refuses alpha at a divisor above 1). Throws
// std::invalid_argument for another divisor or channel count, or when `out` is `internal`.
void upscale_image(const Image& internal, int divisor, int threads, std::vector<uint16_t>& rows, Image& out);

}  // namespace raster
