// The triangle scene: one Embree triangle geometry holding the chosen triangles, committed once.
#include "oracle/reference/triangle_scene.h"

#include <utility>

namespace raster::oracle {

TriangleScene::TriangleScene(EmbreeDevice& device, const std::vector<glm::dvec3>& positions,
                             const std::vector<OracleTriangle>& triangles, std::vector<uint32_t> ids, bool robust,
                             RTCFilterFunctionN filter)
    : ids_(std::move(ids)) {
    scene_ = rtcNewScene(device.get());
    device.check("rtcNewScene");
    rtcSetSceneFlags(scene_, robust ? RTC_SCENE_FLAG_ROBUST : RTC_SCENE_FLAG_NONE);
    if (!ids_.empty()) {
        RTCGeometry mesh = rtcNewGeometry(device.get(), RTC_GEOMETRY_TYPE_TRIANGLE);
        device.check("rtcNewGeometry");
        auto* vertex_buffer = static_cast<float*>(rtcSetNewGeometryBuffer(
            mesh, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), positions.size()));
        auto* index_buffer = static_cast<uint32_t*>(rtcSetNewGeometryBuffer(
            mesh, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(uint32_t), ids_.size()));
        device.check("rtcSetNewGeometryBuffer");
        for (size_t i = 0; i < positions.size(); ++i)
            for (int k = 0; k < 3; ++k) vertex_buffer[3 * i + k] = static_cast<float>(positions[i][k]);
        for (size_t i = 0; i < ids_.size(); ++i)
            for (int k = 0; k < 3; ++k) index_buffer[3 * i + k] = triangles[ids_[i]].vertex[k];
        if (filter) rtcSetGeometryIntersectFilterFunction(mesh, filter);
        rtcCommitGeometry(mesh);
        rtcAttachGeometry(scene_, mesh);
        rtcReleaseGeometry(mesh);
        device.check("attaching the triangle geometry");
    }
    rtcCommitScene(scene_);
    device.check("rtcCommitScene (BVH build)");
}

TriangleScene::~TriangleScene() {
    if (scene_) rtcReleaseScene(scene_);
}

}  // namespace raster::oracle
