// The evidence behind a comparison's pixels (pixel_evidence.h).
#include "harness/comparison/pixel_evidence.h"

#include <cmath>
#include <cstdio>
#include <string>

#include "harness/comparison/comparison.h"
#include "oracle/compare/sample_excuse.h"
#include "oracle/reference/shadow_oracle.h"

namespace raster::harness {
namespace {

// A number as JSON with `digits` significant digits and no more (the evidence file stays small); null if not finite.
nlohmann::json number_value(double value, int digits) {
    if (!std::isfinite(value)) return nullptr;
    char text[40];
    std::snprintf(text, sizeof text, "%.*g", digits, value);
    return nlohmann::json::parse(text);
}

// A float with the digits that read back to it.
nlohmann::json float_value(float value) { return number_value(value, 9); }

nlohmann::json triangle_value(uint32_t triangle) {
    return triangle == kNoTriangle ? nlohmann::json(-1) : nlohmann::json(triangle);
}

nlohmann::json bary_value(const glm::vec3& b) { return {float_value(b.x), float_value(b.y), float_value(b.z)}; }

nlohmann::json bytes_at(const std::vector<uint8_t>& pixels, size_t pixel, int channels) {
    nlohmann::json bytes = nlohmann::json::array();
    for (int k = 0; k < channels; ++k) bytes.push_back(pixels[pixel * size_t(channels) + size_t(k)]);
    return bytes;
}

const char* state_name(oracle::PixelState state) {
    switch (state) {
        case oracle::PixelState::judged: return "judged";
        case oracle::PixelState::ambiguous: return "ambiguous";
        case oracle::PixelState::genuine: return "genuine";
    }
    return "?";
}

constexpr uint8_t kOpenShadowVerdicts = (1u << int(oracle::ShadowVerdict::open_edge)) |
                                        (1u << int(oracle::ShadowVerdict::open_depth)) |
                                        (1u << int(oracle::ShadowVerdict::inconsistent));

class EvidenceWriter {
public:
    explicit EvidenceWriter(const EvidenceInputs& in) : in_(in), c_(*in.comparison), bounds_(*in.bounds) {}

    // Whether pixel `pixel` needs explaining.
    bool notable(size_t pixel) const {
        const auto& classes = c_.visibility.classes;
        const size_t samples = size_t(c_.samples), first = pixel * samples;
        for (size_t s = 0; s < samples && first + s < classes.size(); ++s)
            if (classes[first + s] != oracle::SampleClass::agree) return true;
        if (c_.colour.written && c_.colour.genuine[pixel]) return true;
        if (!bounds_.shadow_seen.empty() && (bounds_.shadow_seen[pixel] & kOpenShadowVerdicts)) return true;
        return !bounds_.layer_open.empty() && bounds_.layer_open[pixel] != oracle::LayerOpen::none;
    }

    nlohmann::json pixel(int x, int y) const {
        const size_t pixel = size_t(y) * size_t(c_.width) + size_t(x);
        nlohmann::json samples = nlohmann::json::array();
        for (int s = 0; s < c_.samples; ++s) samples.push_back(sample(x, y, s));
        nlohmann::json entry = {{"samples", std::move(samples)},
                                {"state", state_name(bounds_.state[pixel])},
                                {"oracle", bytes_at(c_.oracle_image.pixels, pixel, c_.oracle_image.channels)}};
        const Image& file = c_.colour.png_image;
        const bool written = c_.colour.written && file.width == c_.width && file.height == c_.height;
        entry["raster"] = written ? bytes_at(file.pixels, pixel, file.channels) : nlohmann::json(nullptr);
        entry["allowed"] = nullptr;
        if (bounds_.state[pixel] == oracle::PixelState::judged) {
            entry["allowed"] = nlohmann::json::array();
            for (int k = 0; k < bounds_.channels; ++k) {
                const oracle::ByteRange& range = bounds_.ranges[pixel * size_t(bounds_.channels) + size_t(k)];
                entry["allowed"].push_back({range.lo, range.hi});
            }
        }
        entry["colour"] = nullptr;
        if (c_.colour.written) {
            const bool layered = !bounds_.layered.empty() && bounds_.layered[pixel];
            entry["colour"] = !c_.colour.genuine[pixel] ? "agree"
                              : c_.shadows.genuine[pixel] ? "shadow"
                              : layered                   ? "transparency"
                                                          : "genuine";
        }
        if (!bounds_.shadow_seen.empty()) {
            nlohmann::json seen = nlohmann::json::array();
            for (int v = 0; v < oracle::kShadowVerdictCount; ++v)
                if ((bounds_.shadow_seen[pixel] >> v) & 1u) seen.push_back(oracle::to_string(oracle::ShadowVerdict(v)));
            entry["shadows"] = std::move(seen);
        }
        if (!bounds_.layer_open.empty())
            entry["layers"] = bounds_.layer_open[pixel] == oracle::LayerOpen::none
                                  ? nlohmann::json(nullptr)
                                  : nlohmann::json(oracle::to_string(bounds_.layer_open[pixel]));
        return entry;
    }

private:
    nlohmann::json sample(int x, int y, int s) const {
        const VisibilityBuffer& raster = c_.raster.visibility;
        const oracle::SampleBuffer& oracle = c_.oracle_visibility;
        const size_t i = oracle.index(x, y, s);
        const oracle::SampleClass klass = c_.visibility.classes[i];
        const oracle::SampleEntry raster_entry{raster.triangle[i], raster.bary[i], raster.view_depth[i]};
        const glm::dvec2 screen = glm::dvec2(x, y) + (*in_.offsets)[size_t(s)];
        const oracle::SampleExcuse excuse = oracle::sample_excuse(*in_.reference, screen, raster_entry,
                                                                  oracle::sample_entry(oracle, i), klass);
        return {oracle::to_string(klass), triangle_value(raster.triangle[i]), bary_value(raster.bary[i]),
                float_value(raster.view_depth[i]), triangle_value(oracle.triangle[i]), bary_value(oracle.bary[i]),
                float_value(oracle.view_depth[i]), excuse.rule,
                excuse.has_figure ? number_value(excuse.measured, 4) : nlohmann::json(nullptr),
                excuse.has_figure ? number_value(excuse.bound, 4) : nlohmann::json(nullptr)};
    }

    const EvidenceInputs& in_;
    const Comparison& c_;
    const oracle::PixelBounds& bounds_;
};

}  // namespace

nlohmann::json pixel_evidence(const EvidenceInputs& inputs) {
    const Comparison& c = *inputs.comparison;
    const EvidenceWriter writer(inputs);
    nlohmann::json pixels = nlohmann::json::object();
    size_t listed = 0, unlisted = 0;
    for (int y = 0; y < c.height; ++y)
        for (int x = 0; x < c.width; ++x) {
            if (!writer.notable(size_t(y) * size_t(c.width) + size_t(x))) continue;
            if (listed == inputs.max_pixels) {
                ++unlisted;
                continue;
            }
            pixels[std::to_string(x) + "," + std::to_string(y)] = writer.pixel(x, y);
            ++listed;
        }
    return {{"samples", c.samples}, {"channels", inputs.bounds->channels}, {"pixels", std::move(pixels)},
            {"listed", listed}, {"unlisted", unlisted}};
}

}  // namespace raster::harness
