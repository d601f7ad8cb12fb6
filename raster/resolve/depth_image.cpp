// The depth image: each pixel's nearest sample mapped linearly between the image's nearest and farthest depths.
#include "raster/resolve/depth_image.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace raster {

Image depth_image(const VisibilityBuffer& visibility) {
    Image image(visibility.width, visibility.height, 1);
    std::vector<float> nearest(static_cast<size_t>(visibility.width) * visibility.height,
                               std::numeric_limits<float>::infinity());
    float lo = std::numeric_limits<float>::infinity(), hi = 0.0f;
    for (int y = 0; y < visibility.height; ++y)
        for (int x = 0; x < visibility.width; ++x)
            for (int s = 0; s < visibility.samples; ++s) {
                const size_t at = visibility.index(x, y, s);
                if (visibility.triangle[at] == kNoTriangle) continue;
                float& pixel = nearest[static_cast<size_t>(y) * visibility.width + x];
                pixel = std::min(pixel, visibility.view_depth[at]);
                lo = std::min(lo, visibility.view_depth[at]);
                hi = std::max(hi, visibility.view_depth[at]);
            }
    const float range = hi > lo ? hi - lo : 1.0f;
    for (int y = 0; y < visibility.height; ++y)
        for (int x = 0; x < visibility.width; ++x) {
            const float depth = nearest[static_cast<size_t>(y) * visibility.width + x];
            if (depth == std::numeric_limits<float>::infinity()) continue;
            const float t = (depth - lo) / range;  // 0 nearest, 1 farthest
            image.at(x, y)[0] = static_cast<uint8_t>(std::lround(255.0f - t * (255.0f - 32.0f)));
        }
    return image;
}

}  // namespace raster
