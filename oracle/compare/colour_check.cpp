// The colour check: the interval resolve of each judged pixel, then raster's image against it.
#include "oracle/compare/colour_check.h"

#include <algorithm>
#include <cstdlib>
#include <stdexcept>

#include "raster/core/parallel.h"

namespace raster::oracle {
namespace {

// The pixel's samples with the layers raster must composite in front of each (barycentric boxes widened by their
// tolerance, as the opaque samples' are); `open` gets the first reason a sample's layers are left open. True when
// some sample has a layer to composite.
bool gather_layers(const ColourInputs& in, int px, int py, const std::vector<ResolveSample>& box,
                   std::vector<LayeredSample>& layered, LayerOpen& open) {
    const SampleLayers& layers = *in.layers;
    const LayerVerdicts& verdicts = *in.layer_verdicts;
    bool any = false;
    for (size_t s = 0; s < box.size(); ++s) {
        const size_t at = in.oracle->index(px, py, static_cast<int>(s));
        layered[s].opaque = box[s];
        layered[s].layers.clear();
        if (open == LayerOpen::none) open = verdicts.open[at];
        const glm::dvec2 screen = glm::dvec2(px, py) + in.offsets[s];
        for (size_t h = 0; h < layers.count(at); ++h) {
            if (!verdicts.in_front[layers.first[at] + h]) continue;
            const LayerHit& hit = layers.of(at)[h];
            ResolveSample sample{hit.triangle, Interval3(glm::dvec3(hit.bary))};
            const glm::dvec3 tolerance = barycentric_tolerance(*in.reference, hit.triangle, screen);
            for (int k = 0; k < 3; ++k) sample.bary[k] = sample.bary[k].widened(tolerance[k]);
            layered[s].layers.push_back(sample);
            any = true;
        }
    }
    return any;
}

}  // namespace

PixelBounds pixel_bounds(const ColourInputs& in) {
    const SampleBuffer& oracle = *in.oracle;
    const int samples = oracle.samples;
    PixelBounds out;
    out.width = oracle.width;
    out.height = oracle.height;
    out.channels = in.resolve.alpha ? 4 : 3;
    const size_t pixels = static_cast<size_t>(out.width) * out.height;
    out.state.assign(pixels, PixelState::judged);
    out.ranges.assign(pixels * out.channels, ByteRange{});
    if (in.open_shader) {
        out.shadow_seen.assign(pixels, 0);
        out.open_ranges.assign(pixels * out.channels, ByteRange{0, 255});
    }
    if (in.layers) {
        out.layered.assign(pixels, 0);
        out.layer_open.assign(pixels, LayerOpen::none);
    }
    parallel_for(static_cast<size_t>(out.height), in.threads, [&](size_t row) {
        const int py = static_cast<int>(row);
        std::vector<ResolveSample> box(static_cast<size_t>(samples));
        std::vector<LayeredSample> layered(static_cast<size_t>(samples));
        for (int px = 0; px < out.width; ++px) {
            const size_t pixel = static_cast<size_t>(py) * out.width + px;
            bool genuine = false, ambiguous = false;
            for (int s = 0; s < samples; ++s) {
                const size_t at = oracle.index(px, py, s);
                const SampleClass verdict = (*in.classes)[at];
                genuine |= is_genuine(verdict);
                ambiguous |= is_ambiguous(verdict);
                const uint32_t id = oracle.triangle[at];
                box[s] = {id, Interval3(glm::dvec3(oracle.bary[at]))};
                if (id == kNoTriangle || is_genuine(verdict) || is_ambiguous(verdict)) continue;
                const glm::dvec2 screen = glm::dvec2(px, py) + in.offsets[static_cast<size_t>(s)];
                const glm::dvec3 tolerance = barycentric_tolerance(*in.reference, id, screen);
                for (int k = 0; k < 3; ++k) box[s].bary[k] = box[s].bary[k].widened(tolerance[k]);
            }
            const bool has_layers = in.layers && gather_layers(in, px, py, box, layered, out.layer_open[pixel]);
            if (has_layers) out.layered[pixel] = 1;
            if (!genuine && !ambiguous && in.layers && out.layer_open[pixel] != LayerOpen::none) ambiguous = true;
            out.state[pixel] = genuine ? PixelState::genuine : ambiguous ? PixelState::ambiguous : PixelState::judged;
            if (out.state[pixel] != PixelState::judged) continue;
            auto resolve_with = [&](const OracleShader& shader, ShadowTally* tally) {
                return has_layers ? resolve_layered_pixel(shader, in.resolve, in.transparency, layered.data(), tally)
                                  : resolve_pixel(shader, in.resolve, box.data(), tally);
            };
            ShadowTally tally;
            const PixelColour allowed = resolve_with(*in.shader, &tally);
            for (int c = 0; c < out.channels; ++c) out.ranges[pixel * out.channels + c] = byte_range(allowed.channel[c]);
            if (!in.open_shader || tally.seen == 0) continue;  // no light with shadows reaches the pixel
            out.shadow_seen[pixel] = tally.seen;
            const PixelColour open = resolve_with(*in.open_shader, nullptr);
            for (int c = 0; c < out.channels; ++c) out.open_ranges[pixel * out.channels + c] = byte_range(open.channel[c]);
        }
    });
    return out;
}

int IntervalWidths::bin(int width) {
    int bin = 0;
    while (bin + 1 < kIntervalWidthBins && width >= (1 << bin)) ++bin;
    return bin;
}

const char* IntervalWidths::label(int bin) {
    static const char* const kLabels[kIntervalWidthBins] = {"0",     "1",     "2-3",    "4-7",    "8-15",
                                                            "16-31", "32-63", "64-127", "128-255"};
    return bin >= 0 && bin < kIntervalWidthBins ? kLabels[bin] : "?";
}

ColourCheck check_colours(const PixelBounds& bounds, const RasterPixels& image, const OracleImage& oracle) {
    if (oracle.width != bounds.width || oracle.height != bounds.height || oracle.channels != bounds.channels)
        throw std::invalid_argument("check_colours: the oracle's image and the bounds have different sizes");
    ColourCheck out;
    out.genuine_pixels.assign(static_cast<size_t>(bounds.width) * bounds.height, 0);
    out.shadow_pixels.assign(out.genuine_pixels.size(), 0);
    if (image.width != bounds.width || image.height != bounds.height || image.channels < 1) {
        // A file of another size (or none that decodes) is wrong at every pixel.
        std::fill(out.genuine_pixels.begin(), out.genuine_pixels.end(), 1);
        out.judged = out.genuine = out.genuine_pixels.size();
        out.max_difference = 255;
        return out;
    }
    const int channels = std::min(bounds.channels, image.channels);
    for (int y = 0; y < bounds.height; ++y)
        for (int x = 0; x < bounds.width; ++x) {
            const size_t pixel = static_cast<size_t>(y) * bounds.width + x;
            if (bounds.state[pixel] == PixelState::ambiguous) ++out.ambiguous;
            if (bounds.state[pixel] != PixelState::judged) continue;
            int width = 0;
            for (int c = 0; c < bounds.channels; ++c) {
                const ByteRange& range = bounds.ranges[pixel * bounds.channels + c];
                width = std::max(width, range.hi - range.lo);
            }
            ++out.widths.pixels[IntervalWidths::bin(width)];
            out.widths.widest = std::max(out.widths.widest, width);
            const bool wide = width > kWideIntervalLevels;
            ++(wide ? out.ambiguous : out.judged);
            out.wide += wide;
            const uint8_t* shown = image.at(x, y);
            bool inside = true;
            for (int c = 0; c < channels; ++c) {
                const size_t at = pixel * bounds.channels + c;
                inside = inside && bounds.ranges[at].contains(shown[c]);
                const int difference = std::abs(int(shown[c]) - int(oracle.pixels[at]));
                if (!wide) out.max_difference = std::max(out.max_difference, difference);
            }
            if (inside) continue;
            ++out.genuine;
            out.genuine_pixels[pixel] = 1;
            if (!bounds.open_ranges.empty()) {
                bool shadow_explains = true;
                for (int c = 0; c < channels; ++c)
                    shadow_explains = shadow_explains && bounds.open_ranges[pixel * bounds.channels + c].contains(shown[c]);
                out.shadow_pixels[pixel] = shadow_explains;
                out.genuine_shadow += shadow_explains;
            }
            if (out.first.size() >= kListedColourDisagreements) continue;
            ColourDisagreement d;
            d.x = x;
            d.y = y;
            d.channels = channels;
            for (int c = 0; c < channels; ++c) {
                d.raster[c] = shown[c];
                d.oracle[c] = oracle.pixels[pixel * bounds.channels + c];
                d.allowed[c] = bounds.ranges[pixel * bounds.channels + c];
            }
            out.first.push_back(d);
        }
    return out;
}

}  // namespace raster::oracle
