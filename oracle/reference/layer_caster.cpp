// The layer caster: one ray per sample with an intersection filter that keeps every transparent hit.
#include "oracle/reference/layer_caster.h"

#include <algorithm>

#include "oracle/reference/embree_device.h"
#include "oracle/reference/sample_positions.h"
#include "oracle/reference/triangle_scene.h"
#include "raster/core/parallel.h"

namespace raster::oracle {
namespace {

// The intersect context Embree hands back to the filter: the hits of the ray being traced.
struct HitCollector {
    RTCIntersectContext context;  // first: Embree passes a pointer to it
    std::vector<LayerHit>* hits;
};

// Records the hit (t is the ray's tfar while the filter runs) and rejects it, so the ray goes on past it.
void collect_hit(const RTCFilterFunctionNArguments* args) {
    auto* collector = reinterpret_cast<const HitCollector*>(args->context);
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] == 0) continue;
        const float u = RTCHitN_u(args->hit, args->N, i), v = RTCHitN_v(args->hit, args->N, i);
        LayerHit hit;
        hit.triangle = RTCHitN_primID(args->hit, args->N, i);  // an Embree primitive id until mapped
        hit.bary = glm::vec3(1.0f - u - v, u, v);
        hit.view_depth = RTCRayN_tfar(args->ray, args->N, i);
        collector->hits->push_back(hit);
        args->valid[i] = 0;
    }
}

}  // namespace

SampleLayers trace_layers(const Scene& scene, const OracleScene& geometry, const OracleOptions& options) {
    SampleLayers out;
    std::vector<uint32_t> transparent = traced_triangles(scene, geometry, Surfaces::transparent);
    if (transparent.empty()) return out;  // no layers: the oracle's own test (layered_material), not raster's
    const RenderSettings& settings = scene.settings;
    const int threads = options.threads > 0 ? options.threads : default_thread_count();
    EmbreeDevice& device = embree_device_for(threads);
    const TriangleScene view(device, geometry.view, geometry.triangles, std::move(transparent),
                             options.mode == OracleMode::robust, collect_hit);
    const std::vector<glm::dvec2> offsets = sample_offsets_on_grid(settings.samples, settings.pattern, settings.snap_bits);
    const int samples = static_cast<int>(offsets.size());
    const size_t row_samples = static_cast<size_t>(settings.width) * static_cast<size_t>(samples);
    // Rows in parallel, each into its own lists; joined in row order.
    std::vector<std::vector<uint32_t>> row_counts(static_cast<size_t>(settings.height));
    std::vector<std::vector<LayerHit>> row_hits(static_cast<size_t>(settings.height));
    parallel_for(static_cast<size_t>(settings.height), threads, [&](size_t row) {
        const int py = static_cast<int>(row);
        std::vector<LayerHit> hits;
        HitCollector collector;
        rtcInitIntersectContext(&collector.context);
        collector.hits = &hits;
        auto& counts = row_counts[row];
        auto& kept = row_hits[row];
        counts.reserve(row_samples);
        for (size_t i = 0; i < row_samples; ++i) {
            const int px = static_cast<int>(i / static_cast<size_t>(samples));
            const int s = static_cast<int>(i % static_cast<size_t>(samples));
            const glm::dvec2 screen = glm::dvec2(px, py) + offsets[s];
            const glm::dvec3 direction = ray_direction(geometry.camera, screen);
            const glm::dvec3 origin = ray_origin(geometry.camera, screen);  // the eye, 0, unless orthographic
            RTCRayHit ray{};
            ray.ray.org_x = static_cast<float>(origin.x);
            ray.ray.org_y = static_cast<float>(origin.y);
            ray.ray.org_z = static_cast<float>(origin.z);
            ray.ray.dir_x = static_cast<float>(direction.x);
            ray.ray.dir_y = static_cast<float>(direction.y);
            ray.ray.dir_z = static_cast<float>(direction.z);  // exactly -1: t is the view depth
            ray.ray.tnear = scene.camera.near;
            ray.ray.tfar = scene.camera.far;
            ray.ray.mask = 0xFFFFFFFFu;
            ray.hit.geomID = ray.hit.primID = RTC_INVALID_GEOMETRY_ID;
            hits.clear();
            rtcIntersect1(view.get(), &collector.context, &ray);
            // Nearest first; a primitive reported twice (spatial splits) counts once.
            for (LayerHit& hit : hits) hit.triangle = view.scene_triangle(hit.triangle);
            std::sort(hits.begin(), hits.end(), [](const LayerHit& a, const LayerHit& b) {
                return a.view_depth != b.view_depth ? a.view_depth < b.view_depth : a.triangle < b.triangle;
            });
            size_t n = 0;
            for (const LayerHit& hit : hits) {
                bool repeated = false;
                for (size_t k = kept.size() - n; k < kept.size(); ++k) repeated = repeated || kept[k].triangle == hit.triangle;
                if (repeated) continue;
                kept.push_back(hit);
                ++n;
            }
            counts.push_back(static_cast<uint32_t>(n));
        }
    });
    device.check("rtcIntersect1 (transparent layers)");
    out.first.reserve(static_cast<size_t>(settings.height) * row_samples + 1);
    out.first.push_back(0);
    for (size_t row = 0; row < row_counts.size(); ++row) {
        for (uint32_t n : row_counts[row]) out.first.push_back(out.first.back() + n);
        out.hits.insert(out.hits.end(), row_hits[row].begin(), row_hits[row].end());
    }
    return out;
}

}  // namespace raster::oracle
