// Resolve: per-pixel shading of the visibility buffer (SSAA or MSAA), sample averaging and depth visualisation.
#include "raster/resolve.h"

#include <algorithm>
#include <limits>

#include "raster/parallel.h"

namespace raster {

void resolve_image(const VisibilityBuffer& visibility, const Shader& shader, const ResolveParams& params, Image& image) {
    image.width = visibility.width;
    image.height = visibility.height;
    image.channels = params.alpha ? 4 : 3;
    image.pixels.resize(static_cast<size_t>(image.width) * image.height * image.channels);
    const int samples = visibility.samples;
    uint8_t background[4];
    for (int c = 0; c < 3; ++c) background[c] = to_byte(params.background[c]);
    background[3] = 0;
    parallel_for(static_cast<size_t>(visibility.height), params.threads, [&](size_t row) {
        const int y = static_cast<int>(row);
        for (int x = 0; x < visibility.width; ++x) {
            uint8_t* out = image.at(x, y);
            const size_t first = visibility.index(x, y, 0);
            if (samples == 1) {  // the common case, without the averaging
                const uint32_t triangle = visibility.triangle[first];
                if (triangle == kNoTriangle) {
                    std::copy(background, background + image.channels, out);
                    continue;
                }
                const glm::vec3 color = shader.shade(triangle, visibility.bary[first]);
                for (int c = 0; c < 3; ++c) out[c] = to_byte(color[c]);
                if (params.alpha) out[3] = 255;
                continue;
            }
            glm::vec3 sum(0.0f);
            int covered = 0;
            for (int s = 0; s < samples; ++s) {
                const uint32_t triangle = visibility.triangle[first + s];
                if (triangle == kNoTriangle) continue;
                ++covered;
                if (!params.msaa) {
                    sum += shader.shade(triangle, visibility.bary[first + s]);
                    continue;
                }
                // MSAA: only the first sample of each triangle shades, for all of that triangle's samples.
                bool seen = false;
                for (int earlier = 0; earlier < s && !seen; ++earlier) seen = visibility.triangle[first + earlier] == triangle;
                if (seen) continue;
                int count = 1;
                for (int later = s + 1; later < samples; ++later) count += visibility.triangle[first + later] == triangle;
                sum += static_cast<float>(count) * shader.shade(triangle, visibility.bary[first + s]);
            }
            if (covered == 0) {
                std::copy(background, background + image.channels, out);
                continue;
            }
            glm::vec3 color;
            if (params.alpha) color = sum / static_cast<float>(covered);
            else color = (sum + static_cast<float>(samples - covered) * params.background) / static_cast<float>(samples);
            for (int c = 0; c < 3; ++c) out[c] = to_byte(color[c]);
            if (params.alpha) out[3] = to_byte(static_cast<float>(covered) / static_cast<float>(samples));
        }
    });
}

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
