// The layered resolve: per sample a composite of interval colours, the pixel the mean of its samples.
#include "oracle/reference/layer_resolve.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "oracle/reference/precision.h"
#include "raster/core/conventions.h"

namespace raster::oracle {
namespace {

// A layer's colour and opacity boxes.
struct ShadedLayer {
    Interval3 colour;
    Interval opacity;
};

// MSAA: each triangle shaded once, colour and opacity, at the first sample that shows it.
class ShadeOnce {
public:
    ShadeOnce(const OracleShader& shader, bool msaa, ShadowTally* tally) : shader_(shader), msaa_(msaa), tally_(tally) {}
    Interval3 shade(const ResolveSample& sample) { return layer(sample).colour; }
    ShadedLayer layer(const ResolveSample& sample) {
        if (!msaa_) return fresh(sample);
        for (const auto& [id, shaded] : shaded_)
            if (id == sample.triangle) return shaded;
        shaded_.emplace_back(sample.triangle, fresh(sample));
        return shaded_.back().second;
    }

private:
    ShadedLayer fresh(const ResolveSample& sample) const {
        return {shader_.shade(sample.triangle, sample.bary, tally_), shader_.opacity(sample.triangle, sample.bary)};
    }

    const OracleShader& shader_;
    bool msaa_;
    ShadowTally* tally_;
    std::vector<std::pair<uint32_t, ShadedLayer>> shaded_;
};

struct SampleBlend {
    Interval3 colour;  // premultiplied
    Interval alpha;
};

SampleBlend blend(TransparencyMode mode, const LayeredSample& sample, ShadeOnce& shade) {
    Interval3 colour(glm::dvec3(0.0)), weighted(glm::dvec3(0.0));
    Interval3 hull(glm::dvec3(0.0));  // holds every layer colour, and 0
    Interval transmittance(1.0), alpha_sum(0.0);
    double largest = 0.0;
    for (const ResolveSample& layer : sample.layers) {
        const ShadedLayer shaded = shade.layer(layer);
        const Interval a = shaded.opacity;
        const Interval3& c = shaded.colour;
        largest = std::max(largest, c.magnitude());
        colour = colour + (transmittance * a) * c;
        weighted = weighted + a * c;
        for (int k = 0; k < 3; ++k) hull[k] = {std::min(hull[k].lo, c[k].lo), std::max(hull[k].hi, c[k].hi)};
        alpha_sum = alpha_sum + a;
        transmittance = transmittance * (Interval(1.0) - a);
    }
    if (mode == TransparencyMode::weighted) {
        // The weighted mean of the layer colours; where the weights may all be 0 raster writes none, and the mean
        // is within the colours' hull anyway.
        if (alpha_sum.hi <= 0.0) colour = Interval3(glm::dvec3(0.0));
        else if (alpha_sum.lo > 0.0) colour = (Interval(1.0) - transmittance) * (Interval(1.0) / alpha_sum * weighted);
        else colour = (Interval(1.0) - transmittance) * hull;
    }
    SampleBlend out{colour, Interval(1.0) - transmittance};
    if (sample.opaque.triangle != kNoTriangle) {
        const Interval3 c = shade.shade(sample.opaque);
        largest = std::max(largest, c.magnitude());
        out.colour = out.colour + transmittance * c;
        out.alpha = Interval(1.0);
    }
    const int n = static_cast<int>(sample.layers.size());
    const double error = float_gamma(kLayerRoundings * n + kCompositeRoundings) * largest;
    for (int c = 0; c < 3; ++c) out.colour[c] = out.colour[c].widened(error);
    // With every layer's opacity 0 (and no opaque surface) raster's transmittance is exactly 1 and its alpha
    // exactly 0: no widening, so that the RGBA ratio below stays decided.
    if (sample.opaque.triangle != kNoTriangle || alpha_sum.hi > 0.0) out.alpha = out.alpha.widened(float_gamma(2 * n + 1));
    return out;
}

}  // namespace

PixelColour resolve_layered_pixel(const OracleShader& shader, const ResolveSettings& settings, TransparencyMode mode,
                                  const LayeredSample* samples, ShadowTally* tally) {
    ShadeOnce shade(shader, settings.msaa, tally);
    const int count = settings.samples;
    Interval3 sum(glm::dvec3(0.0));
    Interval alpha_sum(0.0);
    double magnitude_sum = 0.0;
    for (int s = 0; s < count; ++s) {
        const SampleBlend b = blend(mode, samples[s], shade);
        Interval3 term = b.colour;
        if (!settings.alpha)  // C + (1 - alpha) background
            for (int c = 0; c < 3; ++c) term[c] = term[c] + (Interval(1.0) - b.alpha) * Interval(settings.background[c]);
        sum = sum + term;
        alpha_sum = alpha_sum + b.alpha;
        magnitude_sum += std::max(term.magnitude(), 1.0);
    }
    // The sums and the division round: gamma(count + 2) of the summed magnitudes.
    const double rounding = float_gamma(count + 3) * magnitude_sum;
    PixelColour out;
    out.channels = settings.alpha ? 4 : 3;
    for (int c = 0; c < 3; ++c) {
        Interval value = (sum[c] / Interval(static_cast<double>(count))).widened(rounding / count);
        if (settings.alpha) {
            // RGB is the colour sum over the alpha sum; where the alpha sum may be 0 raster may write the
            // background, and the ratio is unbounded: any value.
            if (alpha_sum.hi <= 0.0) value = Interval(settings.background[c]);
            else if (alpha_sum.lo <= 0.0) value = Interval(-INFINITY, INFINITY);
            else {
                // The sums' rounding over the alpha sum's, and the alpha sum's own rounding times the ratio.
                value = sum[c] / alpha_sum;
                value = value.widened(rounding / alpha_sum.lo + float_gamma(count + 3) * value.magnitude());
            }
        }
        out.channel[c] = value;
    }
    out.channel[3] = (alpha_sum / Interval(static_cast<double>(count))).widened(rounding / count);
    return out;
}

}  // namespace raster::oracle
