// `raster view`'s render requests: the query parameters of GET /render, parsed and checked, with the message a
// bad one gets (a 400), without any HTTP.
#pragma once

#include <map>
#include <optional>
#include <string>

#include "raster/scene/scene.h"

namespace raster::cli {

// The ranges a request may ask for (docs/viewer.md); beyond them a request is refused, not clamped.
inline constexpr double kMaxYawDegrees = 360.0;
inline constexpr double kMaxPitchDegrees = 180.0;
inline constexpr double kMinDistance = 0.05;  // times the scene's own eye-target distance
inline constexpr double kMaxDistance = 20.0;
inline constexpr int kMaxViewSamples = 16;  // the pattern decides which counts up to this are allowed
inline constexpr double kMaxViewTime = 1e6;  // seconds, either side of 0
inline constexpr int kMaxViewCamera = 1 << 16;

// The viewer's transparency switch: a compositing mode for blended surfaces, or every material drawn opaque.
enum class TransparencyChoice { sorted, weighted, opaque };
const char* to_string(TransparencyChoice choice);

// One frame as a request asks for it. Every field left out keeps the scene's own value (its camera: yaw 0,
// pitch 0, distance 1), so a request alone decides its frame, whatever came before it.
struct ViewRequest {
    std::optional<ShadingMode> shading;
    std::optional<int> samples;
    std::optional<bool> msaa;
    std::optional<TextureFilter> filter;  // every textured material's; none: each keeps the scene's
    double yaw_degrees = 0.0;
    double pitch_degrees = 0.0;
    double distance = 1.0;
    std::optional<double> time;  // an animated scene posed at this instant, in seconds; none: as it was loaded
    std::optional<int> camera;   // a glTF file's camera to draw from (SceneLoadOptions::camera); none: the loaded one
    std::optional<bool> shadows;  // every point and spot light casts shadows, or none does; none: the scene's own
    std::optional<TransparencyChoice> transparency;  // none: the scene's own mode
};

// A request, or what is wrong with it (one line, plain text, naming the parameter and quoting what was sent).
struct ParsedViewRequest {
    ViewRequest request;
    std::string error;  // empty when the request is fine
};

// The query parameters as the server decoded them, name to value (a name may come more than once).
using QueryParameters = std::multimap<std::string, std::string>;

// Parses GET /render's parameters: shading (unlit, flat, gouraud, phong, blinn-phong, cel, gooch), samples
// (integer, 1..16), msaa (0 or 1), filter (nearest, bilinear, trilinear, anisotropic), yaw and pitch (finite
// degrees, |yaw| <= 360, |pitch| <= 180), distance (finite, 0.05..20), time (finite seconds, |time| <= 1e6),
// camera (integer, 0..65536), shadows (on, off) and transparency (sorted, weighted, opaque).
// Refuses unknown or repeated names.
ParsedViewRequest parse_view_request(const QueryParameters& parameters);

}  // namespace raster::cli
