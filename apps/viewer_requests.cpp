// Parsing GET /render's parameters: each name's own parser, each refusal a message quoting what was sent.
#include "apps/viewer_requests.h"

#include <charconv>
#include <cmath>
#include <functional>
#include <sstream>

namespace raster::cli {
namespace {

// What was sent, fit for a one-line message: at most 40 bytes, anything but printable ASCII as '?'.
std::string quoted(const std::string& value) {
    constexpr size_t kMaxShown = 40;
    std::string shown;
    for (size_t i = 0; i < value.size() && i < kMaxShown; ++i) {
        const unsigned char c = static_cast<unsigned char>(value[i]);
        shown += (c >= 0x20 && c < 0x7f) ? static_cast<char>(c) : '?';
    }
    if (value.size() > kMaxShown) shown += "...";
    return "'" + shown + "'";
}

// The whole of `text` as a number, or nothing ("", "1x", " 1", "+1", "0x10" and overflow are not numbers).
template <typename Number>
std::optional<Number> whole_number(const std::string& text) {
    Number value{};
    const char* end = text.data() + text.size();
    const auto [stop, error] = std::from_chars(text.data(), end, value);
    if (error != std::errc() || stop != end || text.empty()) return std::nullopt;
    return value;
}

std::string format_bound(double bound) {
    std::ostringstream text;
    text << bound;
    return text.str();
}

// A finite number in [low, high]; `range_note` follows the range in the message (" degrees").
std::string parse_bounded(const std::string& name, const std::string& value, double low, double high,
                          const std::string& range_note, double& out) {
    const std::optional<double> number = whole_number<double>(value);
    if (!number || !std::isfinite(*number)) return name + " must be a finite number, got " + quoted(value);
    if (*number < low || *number > high)
        return name + " must be in [" + format_bound(low) + ", " + format_bound(high) + "]" + range_note + ", got " +
               quoted(value);
    out = *number;
    return "";
}

using ParameterParser = std::function<std::string(const std::string& value, ViewRequest& request)>;

// Every parameter GET /render knows, in the order messages list them.
const std::map<std::string, ParameterParser>& parameter_parsers() {
    static const std::map<std::string, ParameterParser> parsers = {
        {"shading",
         [](const std::string& value, ViewRequest& request) -> std::string {
             ShadingMode mode{};
             if (!parse_shading_mode(value, mode))
                 return "shading must be unlit, flat, gouraud, phong, blinn-phong, cel or gooch, got " + quoted(value);
             request.shading = mode;
             return "";
         }},
        {"samples",
         [](const std::string& value, ViewRequest& request) -> std::string {
             const std::optional<int> samples = whole_number<int>(value);
             if (!samples) return "samples must be a whole number, got " + quoted(value);
             if (*samples < 1 || *samples > kMaxViewSamples)
                 return "samples must be in [1, " + std::to_string(kMaxViewSamples) + "], got " + quoted(value);
             request.samples = *samples;
             return "";
         }},
        {"msaa",
         [](const std::string& value, ViewRequest& request) -> std::string {
             if (value != "0" && value != "1") return "msaa must be 0 or 1, got " + quoted(value);
             request.msaa = value == "1";
             return "";
         }},
        {"filter",
         [](const std::string& value, ViewRequest& request) -> std::string {
             TextureFilter filter{};
             if (!parse_texture_filter(value, filter))
                 return "filter must be nearest, bilinear, trilinear or anisotropic, got " + quoted(value);
             request.filter = filter;
             return "";
         }},
        {"yaw",
         [](const std::string& value, ViewRequest& request) {
             return parse_bounded("yaw", value, -kMaxYawDegrees, kMaxYawDegrees, " degrees", request.yaw_degrees);
         }},
        {"pitch",
         [](const std::string& value, ViewRequest& request) {
             return parse_bounded("pitch", value, -kMaxPitchDegrees, kMaxPitchDegrees, " degrees",
                                  request.pitch_degrees);
         }},
        {"distance",
         [](const std::string& value, ViewRequest& request) {
             return parse_bounded("distance", value, kMinDistance, kMaxDistance,
                                  " (times the scene's eye-target distance)", request.distance);
         }},
        {"camera",
         [](const std::string& value, ViewRequest& request) -> std::string {
             const std::optional<int> camera = whole_number<int>(value);
             if (!camera || *camera < 0 || *camera > kMaxViewCamera)
                 return "camera must be a whole number in [0, " + std::to_string(kMaxViewCamera) + "], got " + quoted(value);
             request.camera = *camera;
             return "";
         }},
        {"shadows",
         [](const std::string& value, ViewRequest& request) -> std::string {
             if (value != "on" && value != "off") return "shadows must be on or off, got " + quoted(value);
             request.shadows = value == "on";
             return "";
         }},
        {"transparency",
         [](const std::string& value, ViewRequest& request) -> std::string {
             for (const TransparencyChoice choice :
                  {TransparencyChoice::sorted, TransparencyChoice::weighted, TransparencyChoice::opaque})
                 if (value == to_string(choice)) {
                     request.transparency = choice;
                     return "";
                 }
             return "transparency must be sorted, weighted or opaque, got " + quoted(value);
         }},
        {"time",
         [](const std::string& value, ViewRequest& request) {
             double time = 0.0;
             std::string problem = parse_bounded("time", value, -kMaxViewTime, kMaxViewTime, " seconds", time);
             if (problem.empty()) request.time = time;
             return problem;
         }},
    };
    return parsers;
}

std::string known_parameter_names() {
    std::string names;
    for (const auto& [name, parser] : parameter_parsers()) names += (names.empty() ? "" : ", ") + name;
    return names;
}

}  // namespace

const char* to_string(TransparencyChoice choice) {
    return choice == TransparencyChoice::sorted ? "sorted" : choice == TransparencyChoice::weighted ? "weighted" : "opaque";
}

ParsedViewRequest parse_view_request(const QueryParameters& parameters) {
    ParsedViewRequest parsed;
    for (auto at = parameters.begin(); at != parameters.end(); at = parameters.upper_bound(at->first)) {
        const std::string& name = at->first;
        const auto parser = parameter_parsers().find(name);
        if (parser == parameter_parsers().end()) {
            parsed.error = "unknown parameter " + quoted(name) + " (known: " + known_parameter_names() + ")";
            return parsed;
        }
        if (parameters.count(name) > 1) {
            parsed.error = "parameter " + quoted(name) + " is given more than once";
            return parsed;
        }
        parsed.error = parser->second(at->second, parsed.request);
        if (!parsed.error.empty()) return parsed;
    }
    return parsed;
}

}  // namespace raster::cli
