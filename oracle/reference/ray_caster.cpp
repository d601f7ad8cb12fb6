// The Embree oracle's visibility: one triangle geometry in view space, one ray per sample, rows split over threads.
#include "oracle/reference/ray_caster.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "oracle/reference/embree_device.h"
#include "oracle/reference/sample_positions.h"
#include "oracle/reference/triangle_scene.h"
#include "raster/core/parallel.h"
#include "raster/core/stopwatch.h"

namespace raster::oracle {
namespace {

constexpr size_t kPacketSize = 8;  // RTCRayHit8

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }


}  // namespace

const char* to_string(OracleMode mode) { return mode == OracleMode::robust ? "robust" : "fast"; }

std::vector<uint32_t> traced_triangles(const Scene& scene, const OracleScene& geometry, Surfaces surfaces) {
    std::vector<uint32_t> out;
    out.reserve(geometry.triangles.size());
    for (uint32_t id = 0; id < geometry.triangles.size(); ++id) {
        const auto& v = geometry.triangles[id].vertex;
        const bool transparent = layered_material(triangle_material(scene, geometry.triangles[id]));
        if (transparent != (surfaces == Surfaces::transparent)) continue;
        if (!finite(glm::vec3(geometry.view[v[0]])) || !finite(glm::vec3(geometry.view[v[1]])) ||
            !finite(glm::vec3(geometry.view[v[2]])))
            continue;
        if (scene.settings.cull_backfaces &&
            !faces_viewer(geometry.camera, geometry.view[v[0]], geometry.view[v[1]], geometry.view[v[2]]))
            continue;
        out.push_back(id);
    }
    return out;
}

OracleStats render_oracle(const Scene& scene, const OracleScene& geometry, const OracleOptions& options,
                          SampleBuffer& out) {
    OracleStats stats;
    const RenderSettings& settings = scene.settings;
    const int threads = options.threads > 0 ? options.threads : default_thread_count();

    auto start = Clock::now();
    EmbreeDevice& device = embree_device_for(threads);
    const TriangleScene view(device, geometry.view, geometry.triangles, traced_triangles(scene, geometry, Surfaces::opaque),
                             options.mode == OracleMode::robust);
    stats.triangles = view.size();
    stats.ms_build = milliseconds_since(start);

    start = Clock::now();
    const std::vector<glm::dvec2> offsets = sample_offsets_on_grid(settings.samples, settings.pattern, settings.snap_bits);
    const int samples = static_cast<int>(offsets.size());
    out.resize(settings.width, settings.height, samples);
    const float near = scene.camera.near, far = scene.camera.far;
    // Rays go to Embree in packets of 8 consecutive samples of a row (neighbouring samples: coherent rays).
    parallel_for(static_cast<size_t>(settings.height), threads, [&](size_t row) {
        const int py = static_cast<int>(row);
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
        const size_t row_samples = static_cast<size_t>(settings.width) * static_cast<size_t>(samples);
        const size_t row_first = out.index(0, py, 0);
        for (size_t begin = 0; begin < row_samples; begin += kPacketSize) {
            const size_t count = std::min(kPacketSize, row_samples - begin);
            alignas(32) RTCRayHit8 packet;
            alignas(32) int valid[kPacketSize];
            for (size_t k = 0; k < kPacketSize; ++k) {
                valid[k] = k < count ? -1 : 0;
                const size_t i = begin + std::min(k, count - 1);  // inactive lanes repeat a real ray
                const int px = static_cast<int>(i / static_cast<size_t>(samples));
                const int s = static_cast<int>(i % static_cast<size_t>(samples));
                const glm::dvec2 screen = glm::dvec2(px, py) + offsets[s];
                const glm::dvec3 direction = ray_direction(geometry.camera, screen);
                const glm::dvec3 origin = ray_origin(geometry.camera, screen);  // the eye, 0, unless orthographic
                packet.ray.org_x[k] = static_cast<float>(origin.x);
                packet.ray.org_y[k] = static_cast<float>(origin.y);
                packet.ray.org_z[k] = static_cast<float>(origin.z);
                packet.ray.dir_x[k] = static_cast<float>(direction.x);
                packet.ray.dir_y[k] = static_cast<float>(direction.y);
                packet.ray.dir_z[k] = static_cast<float>(direction.z);  // exactly -1: t is the view depth
                packet.ray.tnear[k] = near;
                packet.ray.tfar[k] = far;
                packet.ray.time[k] = 0.0f;
                packet.ray.mask[k] = 0xFFFFFFFFu;
                packet.ray.id[k] = static_cast<unsigned>(k);
                packet.ray.flags[k] = 0;
                packet.hit.geomID[k] = RTC_INVALID_GEOMETRY_ID;
                packet.hit.primID[k] = RTC_INVALID_GEOMETRY_ID;
                packet.hit.instID[0][k] = RTC_INVALID_GEOMETRY_ID;
            }
            rtcIntersect8(valid, view.get(), &context, &packet);
            for (size_t k = 0; k < count; ++k) {
                const size_t at = row_first + begin + k;
                if (packet.hit.geomID[k] == RTC_INVALID_GEOMETRY_ID) continue;  // resize left it empty
                const float u = packet.hit.u[k], v = packet.hit.v[k];
                out.triangle[at] = view.scene_triangle(packet.hit.primID[k]);
                out.bary[at] = glm::vec3(1.0f - u - v, u, v);
                out.view_depth[at] = packet.ray.tfar[k];
            }
        }
    });
    device.check("rtcIntersect8");
    stats.ms_trace = milliseconds_since(start);
    return stats;
}

}  // namespace raster::oracle
