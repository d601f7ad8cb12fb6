// The orbit's arithmetic, in double precision: the elevation, its clamp and two Rodrigues rotations.
#include "apps/viewer_orbit.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace raster::cli {
namespace {

constexpr double kDegreesToRadians = 3.14159265358979323846 / 180.0;

// v rotated right-handedly by `radians` about the unit axis `axis`. An angle of 0 gives v exactly back.
glm::dvec3 rotate(const glm::dvec3& v, const glm::dvec3& axis, double radians) {
    const double c = std::cos(radians), s = std::sin(radians);
    return v * c + glm::cross(axis, v) * s + axis * (glm::dot(axis, v) * (1.0 - c));
}

glm::dvec3 offset_of(const Camera& camera) { return glm::dvec3(camera.eye) - glm::dvec3(camera.target); }

}  // namespace

double eye_elevation_degrees(const Camera& camera) {
    const glm::dvec3 direction = glm::normalize(offset_of(camera));
    const double sine = std::clamp(glm::dot(direction, glm::normalize(glm::dvec3(camera.up))), -1.0, 1.0);
    return std::asin(sine) / kDegreesToRadians;
}

double orbit_elevation_limit_degrees(const Camera& camera) {
    return std::max(kMaxOrbitElevationDegrees, std::abs(eye_elevation_degrees(camera)));
}

Camera orbit_camera(const Camera& camera, double yaw_degrees, double pitch_degrees, double distance) {
    const glm::dvec3 offset = offset_of(camera);
    const glm::dvec3 up = glm::normalize(glm::dvec3(camera.up));
    // A valid scene's view direction is not parallel to up, so the side axis exists.
    const glm::dvec3 side = glm::normalize(glm::cross(offset, up));
    const double elevation = eye_elevation_degrees(camera);
    const double limit = orbit_elevation_limit_degrees(camera);
    const double pitch = std::clamp(elevation + pitch_degrees, -limit, limit) - elevation;
    const glm::dvec3 pitched = rotate(offset, side, pitch * kDegreesToRadians);
    const glm::dvec3 orbited = rotate(pitched, up, yaw_degrees * kDegreesToRadians) * distance;
    Camera result = camera;
    result.eye = glm::vec3(glm::dvec3(camera.target) + orbited);
    result.near = static_cast<float>(camera.near * std::min(1.0, distance));
    result.far = static_cast<float>(camera.far * std::max(1.0, distance));
    // An orthographic view does not shrink with distance: the zoom scales its view volume instead.
    result.ortho_height = static_cast<float>(camera.ortho_height * distance);
    return result;
}

}  // namespace raster::cli
