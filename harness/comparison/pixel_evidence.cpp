// The evidence behind a comparison's pixels (pixel_evidence.h).
#include "harness/comparison/pixel_evidence.h"

#include <cmath>
#include <cstdio>
#include <string>

namespace raster::harness {
namespace {

// A float as JSON with the digits that read back to it, and no more (the evidence file stays small).
nlohmann::json float_value(float value) {
    if (!std::isfinite(value)) return nullptr;
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", value);
    return nlohmann::json::parse(text);
}

nlohmann::json triangle_value(uint32_t triangle) {
    return triangle == kNoTriangle ? nlohmann::json(-1) : nlohmann::json(triangle);
}

nlohmann::json bary_value(const glm::vec3& b) { return {float_value(b.x), float_value(b.y), float_value(b.z)}; }

}  // namespace

nlohmann::json pixel_evidence(const Comparison& c, size_t max_pixels) {
    const auto& classes = c.visibility.classes;
    const VisibilityBuffer& raster = c.raster.visibility;
    const oracle::SampleBuffer& oracle = c.oracle_visibility;
    const size_t samples = static_cast<size_t>(c.samples);
    nlohmann::json pixels = nlohmann::json::object();
    size_t listed = 0, unlisted = 0;
    for (int y = 0; y < c.height; ++y)
        for (int x = 0; x < c.width; ++x) {
            const size_t first = (static_cast<size_t>(y) * static_cast<size_t>(c.width) + static_cast<size_t>(x)) * samples;
            bool notable = false;
            for (size_t s = 0; s < samples && first + s < classes.size(); ++s)
                notable |= classes[first + s] != oracle::SampleClass::agree;
            if (!notable) continue;
            if (listed == max_pixels) {
                ++unlisted;
                continue;
            }
            nlohmann::json list = nlohmann::json::array();
            for (size_t s = 0; s < samples; ++s) {
                const size_t i = first + s;
                list.push_back({oracle::to_string(classes[i]), triangle_value(raster.triangle[i]),
                                bary_value(raster.bary[i]), float_value(raster.view_depth[i]),
                                triangle_value(oracle.triangle[i]), bary_value(oracle.bary[i]),
                                float_value(oracle.view_depth[i])});
            }
            pixels[std::to_string(x) + "," + std::to_string(y)] = std::move(list);
            ++listed;
        }
    return {{"samples", c.samples}, {"pixels", pixels}, {"listed", listed}, {"unlisted", unlisted}};
}

}  // namespace raster::harness
