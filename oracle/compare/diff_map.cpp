// The disagreement map: per pixel, the worst class among its samples, then its colour's.
#include "oracle/compare/diff_map.h"

#include "oracle/reference/shadow_oracle.h"

#include <algorithm>
#include <cstdio>

namespace raster::oracle {

const std::vector<DiffMapKey>& diff_map_legend() {
    static const std::vector<DiffMapKey> legend = {
        {{kGenuineColor[0], kGenuineColor[1], kGenuineColor[2]}, "a genuine sample"},
        {{kColourDisagreementColor[0], kColourDisagreementColor[1], kColourDisagreementColor[2]},
         "a colour outside the range the oracle allows"},
        {{kShadowDisagreementColor[0], kShadowDisagreementColor[1], kShadowDisagreementColor[2]},
         "a colour a shadow test explains"},
        {{kAmbiguousColor[0], kAmbiguousColor[1], kAmbiguousColor[2]},
         "ambiguous: allowed by the precision model, or transparent layers left open"},
        {{kShadowOpenColor[0], kShadowOpenColor[1], kShadowOpenColor[2]}, "a shadow verdict left open"},
        {{90, 90, 90}, "agreeing (raster's image, dimmed to grey)"},
    };
    return legend;
}

std::string css_colour(const DiffMapKey& key) {
    char colour[8];
    std::snprintf(colour, sizeof colour, "#%02x%02x%02x", key.rgb[0], key.rgb[1], key.rgb[2]);
    return colour;
}

OracleImage diff_map(const std::vector<SampleClass>& classes, int samples, const std::vector<uint8_t>& colour_genuine,
               const RasterPixels& raster_image, const ShadowLayers& shadows) {
    auto flag = [](const std::vector<uint8_t>* layer, size_t pixel) {
        return layer && !layer->empty() ? (*layer)[pixel] : uint8_t{0};
    };
    uint8_t open_verdicts = 0;
    for (int v = 0; v < kShadowVerdictCount; ++v)
        if (is_open(static_cast<ShadowVerdict>(v))) open_verdicts |= static_cast<uint8_t>(1u << v);
    OracleImage map;
    map.width = raster_image.width;
    map.height = raster_image.height;
    map.channels = 3;
    map.pixels.assign(static_cast<size_t>(map.width) * map.height * 3, 0);
    for (int y = 0; y < map.height; ++y) {
        for (int x = 0; x < map.width; ++x) {
            const size_t pixel = static_cast<size_t>(y) * map.width + x;
            const size_t first = pixel * static_cast<size_t>(samples);
            bool genuine = false, ambiguous = false;
            for (int s = 0; s < samples; ++s) {
                genuine |= is_genuine(classes[first + s]);
                ambiguous |= is_ambiguous(classes[first + s]);
            }
            ambiguous |= flag(shadows.layers_open, pixel) != 0;
            uint8_t* out = &map.pixels[pixel * 3];
            if (genuine || colour_genuine[pixel] || ambiguous) {
                std::copy_n(genuine                            ? kGenuineColor
                            : flag(shadows.genuine, pixel)     ? kShadowDisagreementColor
                            : colour_genuine[pixel]            ? kColourDisagreementColor
                                                               : kAmbiguousColor,
                            3, out);
                continue;
            }
            if (flag(shadows.seen, pixel) & open_verdicts) {
                std::copy_n(kShadowOpenColor, 3, out);
                continue;
            }
            const uint8_t* in = raster_image.at(x, y);
            const float luma = raster_image.channels >= 3 ? 0.2126f * in[0] + 0.7152f * in[1] + 0.0722f * in[2] : in[0];
            const auto grey = static_cast<uint8_t>(20.0f + 0.35f * luma + 0.5f);
            out[0] = out[1] = out[2] = grey;
        }
    }
    return map;
}

}  // namespace raster::oracle
