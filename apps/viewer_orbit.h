// `raster view`'s orbit: the scene's camera turned about its own target and up vector, by yaw and pitch in degrees,
// at a distance relative to its own.
#pragma once

#include "raster/scene/scene.h"

namespace raster::cli {

// The eye's elevation is kept within this many degrees of the plane through the target perpendicular to up (or
// within the scene's own elevation, when that is steeper), so the view direction never meets the up vector.
inline constexpr double kMaxOrbitElevationDegrees = 89.0;

// The scene eye's elevation in degrees: the angle between eye - target and the plane perpendicular to up.
double eye_elevation_degrees(const Camera& camera);

// The largest elevation the orbit reaches: max(kMaxOrbitElevationDegrees, |eye_elevation_degrees(camera)|).
double orbit_elevation_limit_degrees(const Camera& camera);

// The scene's camera orbited (docs/viewer.md). With o = eye - target, u = normalize(up), s = normalize(o x u),
// e0 = eye_elevation_degrees(camera) and L = orbit_elevation_limit_degrees(camera):
//   pitch' = clamp(e0 + pitch, -L, L) - e0
//   eye'   = target + distance * R(u, yaw) R(s, pitch') o
// R(a, angle) rotates right-handedly about the unit axis a (Rodrigues' formula, in double precision), so positive
// yaw turns the eye counter-clockwise seen from above (up towards the viewer) and positive pitch raises it.
// Moving closer divides near by the factor and moving away multiplies far by it (near * min(1, distance),
// far * max(1, distance)), so what the scene's frustum holds stays in it at any distance. Target, up and the field
// of view stay the scene's; yaw 0, pitch 0, distance 1 gives the scene's camera.
Camera orbit_camera(const Camera& camera, double yaw_degrees, double pitch_degrees, double distance);

}  // namespace raster::cli
