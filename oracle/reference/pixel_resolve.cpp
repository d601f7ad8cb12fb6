// The oracle's resolve: SSAA, MSAA and alpha over interval colours, with the averaging's float rounding.
#include "oracle/reference/pixel_resolve.h"

#include <cmath>

#include "oracle/reference/precision.h"
#include "raster/core/conventions.h"

namespace raster::oracle {

PixelColour resolve_pixel(const OracleShader& shader, const ResolveSettings& settings, const ResolveSample* samples,
                          ShadowTally* tally) {
    const int count = settings.samples;
    Interval3 sum(glm::dvec3(0.0));
    glm::dvec3 magnitude(0.0);  // of the summed terms, for the sum's rounding
    int covered = 0;
    for (int s = 0; s < count; ++s) {
        const uint32_t id = samples[s].triangle;
        if (id == kNoTriangle) continue;
        ++covered;
        int weight = 1;
        if (settings.msaa) {
            bool first = true;
            for (int earlier = 0; earlier < s && first; ++earlier) first = samples[earlier].triangle != id;
            if (!first) continue;
            weight = 0;
            for (int later = s; later < count; ++later) weight += samples[later].triangle == id;
        }
        const Interval3 colour = shader.shade(id, samples[s].bary, tally);
        sum = sum + Interval(static_cast<double>(weight)) * colour;
        for (int c = 0; c < 3; ++c) magnitude[c] += weight * colour[c].magnitude();
    }
    PixelColour out;
    out.channels = settings.alpha ? 4 : 3;
    if (covered == 0) {
        for (int c = 0; c < 3; ++c) out.channel[c] = Interval(settings.background[c]);
        out.channel[3] = Interval(0.0);
        return out;
    }
    // The background's share, then the division; the weights' products, the sum and the division round.
    const double divisor = settings.alpha ? covered : count;
    const double rounding = float_gamma(count + 2);
    for (int c = 0; c < 3; ++c) {
        Interval total = sum[c];
        double total_magnitude = magnitude[c];
        if (!settings.alpha) {
            total = total + Interval((count - covered) * settings.background[c]);
            total_magnitude += (count - covered) * std::fabs(settings.background[c]);
        }
        out.channel[c] = (total / Interval(divisor)).widened(rounding * total_magnitude / divisor);
    }
    out.channel[3] = Interval(static_cast<double>(covered) / count).widened(kFloatUnitRoundoff);
    return out;
}

}  // namespace raster::oracle
