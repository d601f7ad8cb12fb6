// An Embree scene of some of the oracle's triangles, at positions the caller chooses (view space for the camera's
// rays, world space for the shadow rays), each vertex rounded to float as Embree takes it.
#pragma once

#include <cstdint>
#include <vector>

#include <embree3/rtcore.h>
#include <glm/vec3.hpp>

#include "oracle/reference/embree_device.h"
#include "oracle/reference/scene_geometry.h"

namespace raster::oracle {

class TriangleScene {
public:
    // `ids` index `triangles`, whose vertices index `positions`. Robust unless `robust` is false; `filter`, when
    // given, is every hit's intersection filter. Throws OracleError when Embree fails.
    TriangleScene(EmbreeDevice& device, const std::vector<glm::dvec3>& positions,
                  const std::vector<OracleTriangle>& triangles, std::vector<uint32_t> ids, bool robust,
                  RTCFilterFunctionN filter = nullptr);
    ~TriangleScene();
    TriangleScene(const TriangleScene&) = delete;
    TriangleScene& operator=(const TriangleScene&) = delete;
    RTCScene get() const { return scene_; }
    // The scene triangle of an Embree primitive id.
    uint32_t scene_triangle(unsigned primitive) const { return ids_[primitive]; }
    size_t size() const { return ids_.size(); }

private:
    RTCScene scene_ = nullptr;
    std::vector<uint32_t> ids_;
};

}  // namespace raster::oracle
