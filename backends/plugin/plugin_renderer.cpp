// The plugin backend behind the renderer seam (plugin_renderer.h).
#include "backends/plugin/plugin_renderer.h"

#include <stdexcept>
#include <vector>

#include "raster/core/stopwatch.h"
#include "raster/frame/render.h"
#include "raster/geometry/front_end.h"
#include "raster/geometry/vertex_stage.h"
#include "raster/resolve/resolve.h"

namespace raster::plugin {

PluginBackend::PluginBackend(const PluginLibrary& library, const Scene& scene) : library_(library), scene_(scene) {}

OpaqueDrawStats PluginBackend::draw_opaque(const OpaqueDraw& draw, RenderResult& result) const {
    if (!draw.geometry) throw std::logic_error("the plugin backend needs the frame's clip-space triangles");
    const TransformedScene& geometry = *draw.geometry;
    const FrameParams& params = draw.frame;
    ClipSpaceFrame frame;
    frame.width = params.width;
    frame.height = params.height;
    frame.sample_offsets = params.sample_offsets;
    frame.subpixel_bits = params.snap_bits;
    frame.cull_backfaces = scene_.settings.cull_backfaces;
    frame.orthographic = params.clip.orthographic;
    frame.near_plane = params.clip.near;
    frame.far_plane = params.clip.far;
    // The opaque triangles, in scene order; scene_ids maps the plugin's indices back.
    const std::vector<uint8_t> transparent = transparent_triangles(scene_);
    std::vector<uint32_t> scene_ids;
    scene_ids.reserve(geometry.triangles.size());
    frame.triangles.reserve(geometry.triangles.size());
    for (size_t t = 0; t < geometry.triangles.size(); ++t) {
        if (!transparent.empty() && transparent[t]) continue;
        const TriangleIndices& corners = geometry.triangles[t];
        frame.triangles.push_back({geometry.clip[corners.v[0]], geometry.clip[corners.v[1]], geometry.clip[corners.v[2]]});
        scene_ids.push_back(static_cast<uint32_t>(t));
    }

    OpaqueDrawStats stats;
    auto stage_start = Clock::now();
    library_.draw(frame, result.visibility);
    for (uint32_t& id : result.visibility.triangle) {
        if (id == kNoTriangle) continue;
        id = scene_ids[id];
        ++stats.covered_samples;
    }
    stats.ms_raster = milliseconds_since(stage_start);
    stage_start = Clock::now();
    resolve_image(result.visibility, draw.resolver, params.threads, result.image);
    stats.ms_shade = milliseconds_since(stage_start);
    return stats;
}

void PluginBackend::draw_depth(const FrameParams& frame, RenderWorkspace& workspace, float* view_depth) const {
    raster_backend(RasterPath::tiled).draw_depth(frame, workspace, view_depth);
}

void PluginRenderer::render_into(const Scene& scene, const RenderOptions& options, RenderResult& result) const {
    // The precision modes are raster's own, and they set what the comparison judges: a plugin, which is told none of
    // them, is judged under the exact ones.
    if (!exact_precision(scene.settings.modes))
        throw InputError("the plugin backend runs a plugin under the exact precision modes only (no --edges, "
                         "--interpolation, --depth-format or --clipping): they are raster's own, and they would "
                         "leave classes of the plugin's samples unjudged");
    render_frame(scene, options, PluginBackend(*library_, scene), result);
}

}  // namespace raster::plugin
