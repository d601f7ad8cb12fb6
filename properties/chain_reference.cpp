// The scene-file properties' shared reference: the chain in double and the documented camera (chain_reference.h).
#include "properties/chain_reference.h"

#include <cmath>

#include <glm/geometric.hpp>

namespace raster::properties {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kEyeZ = 8.0;
constexpr double kFovDegrees = 45.0;

}  // namespace

const char* const kChainFramePreamble =
    "image: {width: 64, height: 64}\n"
    "camera: {eye: [0, 0, 8], target: [0, 0, 0], up: [0, 1, 0], fov: 45, near: 1, far: 100}\n"
    "render: {shading: unlit}\n";

glm::dvec3 chain_moved(const ScaleRotateTranslate& chain, const glm::dvec3& object) {
    const glm::dvec3 p = object * glm::dvec3(chain.scale);
    const glm::dvec3 k = glm::normalize(glm::dvec3(chain.axis));
    const double radians = static_cast<double>(chain.degrees) * kPi / 180.0;
    const double cosine = std::cos(radians), sine = std::sin(radians);
    const glm::dvec3 rotated = p * cosine + glm::cross(k, p) * sine + k * (glm::dot(k, p) * (1.0 - cosine));
    return rotated + glm::dvec3(chain.offset);
}

glm::dvec2 chain_frame_screen_of(const glm::dvec3& world) {
    const double focal = 1.0 / std::tan(kFovDegrees * kPi / 360.0);
    const double depth = kEyeZ - world.z;  // -z_view
    const double ndc_x = focal * world.x / depth, ndc_y = focal * world.y / depth;
    return {(ndc_x + 1.0) * 0.5 * kChainFrameSide, (1.0 - ndc_y) * 0.5 * kChainFrameSide};
}

double signed_distance(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& p) {
    const glm::dvec2 edge = b - a;
    const double length = glm::length(edge);
    return length > 0.0 ? (edge.x * (p.y - a.y) - edge.y * (p.x - a.x)) / length : 0.0;
}

}  // namespace raster::properties
