// The oracle's image: point boxes at the oracle's own barycentrics through its resolve, the exact bytes of each.
#include "oracle/reference/oracle_image.h"

#include "oracle/reference/shading_precision.h"
#include "raster/core/parallel.h"

namespace raster::oracle {

OracleImage render_image(const OracleShader& shader, const SampleBuffer& visibility, const ResolveSettings& settings,
                         int threads, const SampleLayers* layers, TransparencyMode mode) {
    OracleImage image;
    image.width = visibility.width;
    image.height = visibility.height;
    image.channels = settings.alpha ? 4 : 3;
    image.pixels.assign(static_cast<size_t>(image.width) * image.height * image.channels, 0);
    parallel_for(static_cast<size_t>(image.height), threads, [&](size_t row) {
        const int y = static_cast<int>(row);
        std::vector<ResolveSample> samples(static_cast<size_t>(visibility.samples));
        std::vector<LayeredSample> layered(samples.size());
        for (int x = 0; x < image.width; ++x) {
            bool any_layer = false;
            for (int s = 0; s < visibility.samples; ++s) {
                const size_t at = visibility.index(x, y, s);
                samples[s] = {visibility.triangle[at], Interval3(glm::dvec3(visibility.bary[at]))};
                if (!layers) continue;
                layered[s].opaque = samples[s];
                layered[s].layers.clear();
                for (size_t h = 0; h < layers->count(at); ++h) {
                    const LayerHit& hit = layers->of(at)[h];
                    if (samples[s].triangle != kNoTriangle && !(hit.view_depth < visibility.view_depth[at])) continue;
                    layered[s].layers.push_back({hit.triangle, Interval3(glm::dvec3(hit.bary))});
                    any_layer = true;
                }
            }
            const PixelColour colour = any_layer ? resolve_layered_pixel(shader, settings, mode, layered.data())
                                                 : resolve_pixel(shader, settings, samples.data());
            uint8_t* out = &image.pixels[(static_cast<size_t>(y) * image.width + x) * image.channels];
            // A point's interval is only its float-error allowance wide: its midpoint is the formula's value.
            for (int c = 0; c < image.channels; ++c)
                out[c] = static_cast<uint8_t>(exact_byte(0.5 * (colour.channel[c].lo + colour.channel[c].hi)));
        }
    });
    return image;
}

}  // namespace raster::oracle
