// The depth image check: the definition in double over raster's samples, each pixel's allowed bytes, the file.
#include "oracle/compare/depth_image_check.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "raster/core/conventions.h"

namespace raster::oracle {
namespace {

constexpr size_t kListed = 20;

int round_half_up(double v) { return static_cast<int>(std::floor(v + 0.5)); }

}  // namespace

DepthImageCheck check_depth_image(const RasterSamples& samples, const RasterPixels& image) {
    DepthImageCheck out;
    const size_t pixels = static_cast<size_t>(samples.width) * samples.height;
    out.pixels = pixels;
    out.genuine_pixels.assign(pixels, 0);
    if (image.width != samples.width || image.height != samples.height || image.channels < 1) {
        std::fill(out.genuine_pixels.begin(), out.genuine_pixels.end(), 1);
        out.genuine = pixels;
        out.max_difference = 255;
        return out;
    }
    constexpr double kNone = std::numeric_limits<double>::infinity();
    std::vector<double> nearest(pixels, kNone);
    double lo = kNone, hi = -kNone;
    for (size_t pixel = 0; pixel < pixels; ++pixel)
        for (int s = 0; s < samples.samples; ++s) {
            const size_t at = pixel * static_cast<size_t>(samples.samples) + static_cast<size_t>(s);
            if (samples.triangle[at] == kNoTriangle) continue;
            const double depth = samples.view_depth[at];
            nearest[pixel] = std::min(nearest[pixel], depth);
            lo = std::min(lo, depth);
            hi = std::max(hi, depth);
        }
    const double range = hi > lo ? hi - lo : 1.0;
    for (int y = 0; y < samples.height; ++y)
        for (int x = 0; x < samples.width; ++x) {
            const size_t pixel = static_cast<size_t>(y) * samples.width + x;
            int allowed_lo = 0, allowed_hi = 0;
            if (nearest[pixel] != kNone) {
                const double value = 255.0 - 223.0 * (nearest[pixel] - lo) / range;
                allowed_lo = round_half_up(value - kDepthByteSlack);
                allowed_hi = round_half_up(value + kDepthByteSlack);
            }
            const int file = image.at(x, y)[0];
            const int off = file < allowed_lo ? allowed_lo - file : file > allowed_hi ? file - allowed_hi : 0;
            out.max_difference = std::max(out.max_difference, off);
            if (off == 0) continue;
            out.genuine_pixels[pixel] = 1;
            ++out.genuine;
            if (out.first.size() < kListed) out.first.push_back({x, y, file, allowed_lo, allowed_hi});
        }
    return out;
}

}  // namespace raster::oracle
