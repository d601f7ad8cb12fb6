// The reduced-resolution upscale written straight from its convention (docs/conventions.md "Reduced resolution"),
// in double, pixel by pixel: what tests hold raster's integer two-pass upscale (resolve/upscale.h) to.
#pragma once

#include <algorithm>
#include <cmath>

#include "raster/image/image.h"

namespace raster::test {

// Output pixel (x, y) is centred at internal (u, v) = ((x + 1/2) / d - 1/2, (y + 1/2) / d - 1/2); it blends the
// four internal pixels around that point (indices clamped to the image) bilinearly, and rounds half up. For
// d = 2 and 4 every weight is a multiple of 1/8, so double holds each blend exactly.
inline Image reference_upscale(const Image& internal, int d) {
    Image out(internal.width * d, internal.height * d, internal.channels);
    auto axis = [d](int x, int size, int& first, int& second, double& fraction) {
        const double u = (x + 0.5) / d - 0.5;
        const double below = std::floor(u);
        fraction = u - below;
        first = std::clamp(static_cast<int>(below), 0, size - 1);
        second = std::clamp(static_cast<int>(below) + 1, 0, size - 1);
    };
    for (int y = 0; y < out.height; ++y)
        for (int x = 0; x < out.width; ++x) {
            int x0, x1, y0, y1;
            double fx, fy;
            axis(x, internal.width, x0, x1, fx);
            axis(y, internal.height, y0, y1, fy);
            for (int c = 0; c < out.channels; ++c) {
                const double top = (1 - fx) * internal.at(x0, y0)[c] + fx * internal.at(x1, y0)[c];
                const double bottom = (1 - fx) * internal.at(x0, y1)[c] + fx * internal.at(x1, y1)[c];
                out.at(x, y)[c] = static_cast<uint8_t>(std::floor((1 - fy) * top + fy * bottom + 0.5));
            }
        }
    return out;
}

}  // namespace raster::test
