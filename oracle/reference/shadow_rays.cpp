// Shadow rays through Embree: the casting triangles in one world-space geometry, one closest-hit ray per query.
#include "oracle/reference/shadow_rays.h"

#include <cmath>
#include <limits>
#include <utility>

#include <embree3/rtcore.h>
#include <glm/geometric.hpp>

#include "oracle/reference/embree_device.h"
#include "oracle/reference/triangle_scene.h"

namespace raster::oracle {

// Beyond the point by this fraction, so that the receiver's own surface is always met (and read as the receiver).
constexpr double kPastThePoint = 1e-6;

ShadowRays::ShadowRays(const OracleScene& geometry, const std::vector<uint8_t>& casts, int threads)
    : geometry_(geometry) {
    std::vector<uint32_t> ids;
    for (uint32_t id = 0; id < geometry.triangles.size(); ++id)
        if (casts[id]) ids.push_back(id);
    scene_ = std::make_unique<TriangleScene>(embree_device_for(threads), geometry.world, geometry.triangles,
                                             std::move(ids), /*robust=*/true);
}

ShadowRays::~ShadowRays() = default;

double ShadowRays::first_surface(const glm::dvec3& light, const glm::dvec3& point) const {
    constexpr double kNone = std::numeric_limits<double>::infinity();
    if (scene_->size() == 0) return kNone;
    const glm::dvec3 direction = point - light;
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit ray{};
    ray.ray.org_x = static_cast<float>(light.x);
    ray.ray.org_y = static_cast<float>(light.y);
    ray.ray.org_z = static_cast<float>(light.z);
    ray.ray.dir_x = static_cast<float>(direction.x);
    ray.ray.dir_y = static_cast<float>(direction.y);
    ray.ray.dir_z = static_cast<float>(direction.z);
    ray.ray.tnear = 0.0f;
    ray.ray.tfar = static_cast<float>(1.0 + kPastThePoint);
    ray.ray.mask = 0xFFFFFFFFu;
    ray.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    ray.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene_->get(), &context, &ray);
    if (ray.hit.geomID == RTC_INVALID_GEOMETRY_ID) return kNone;
    // Where the exact ray meets the hit triangle's exact plane.
    const auto& v = geometry_.triangles[scene_->scene_triangle(ray.hit.primID)].vertex;
    const glm::dvec3 normal = glm::cross(geometry_.world[v[1]] - geometry_.world[v[0]], geometry_.world[v[2]] - geometry_.world[v[0]]);
    const double denominator = glm::dot(normal, direction);
    if (!(std::fabs(denominator) > 0.0)) return static_cast<double>(ray.ray.tfar);  // seen edge-on: Embree's
    return glm::dot(normal, geometry_.world[v[0]] - light) / denominator;
}

}  // namespace raster::oracle
