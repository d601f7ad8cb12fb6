// The oracle's shadow rays: Embree (robust) over the scene's triangles that cast shadows, in world space, asked for
// the first surface on the segment from a light to a point. Embree answers which triangle the ray meets; where on
// the segment is the oracle's own, from that triangle's exact plane in double.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include <glm/vec3.hpp>

#include "oracle/reference/scene_geometry.h"
#include "oracle/reference/triangle_scene.h"

namespace raster::oracle {

class ShadowRays {
public:
    // The triangles with casts[id] set; `threads` as the comparison's (the device is kept per thread count).
    ShadowRays(const OracleScene& geometry, const std::vector<uint8_t>& casts, int threads);
    ~ShadowRays();
    ShadowRays(const ShadowRays&) = delete;
    ShadowRays& operator=(const ShadowRays&) = delete;

    // The first surface from `light` towards `point`, as the fraction of the way there its exact plane is met
    // (in [0, 1 + 1e-6]), or infinity when Embree reports none before the point.
    double first_surface(const glm::dvec3& light, const glm::dvec3& point) const;

private:
    const OracleScene& geometry_;
    std::unique_ptr<TriangleScene> scene_;  // the casting triangles in world space
};

}  // namespace raster::oracle
