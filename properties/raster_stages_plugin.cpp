// raster's stages as a plugin (raster_stages_plugin.h).
#include "properties/raster_stages_plugin.h"

#include <cstring>
#include <vector>

#include "raster/geometry/front_end.h"
#include "raster/rasterize/reference_rasterizer.h"

namespace raster::properties {
namespace {

uint32_t abi_version() { return RASTER_PLUGIN_ABI_VERSION; }
const char* name() { return "raster's stages"; }

int draw(const raster_plugin_frame* in, raster_plugin_samples* out, bool barycentrics) {
    std::vector<glm::vec2> offsets(static_cast<size_t>(in->samples));
    std::memcpy(offsets.data(), in->sample_offsets, offsets.size() * sizeof(glm::vec2));
    FrameParams params = frame_params(in->width, in->height, in->subpixel_bits, offsets);
    params.clip = ClipVolume{in->near_plane, in->far_plane, 1.0, in->orthographic != 0};
    params.threads = 1;  // a property draws thousands of small frames: no thread pool for each
    TransformedScene geometry;
    for (uint32_t t = 0; t < in->triangle_count; ++t) {
        for (int k = 0; k < 3; ++k) {
            const float* v = in->clip_positions + 12 * size_t{t} + 4 * k;
            geometry.clip.emplace_back(v[0], v[1], v[2], v[3]);
        }
        geometry.triangles.push_back({{3 * t, 3 * t + 1, 3 * t + 2}});
    }
    // Kept from frame to frame: a property draws thousands of frames, and fresh planes cost their page faults.
    thread_local VisibilityBuffer visibility;
    rasterize_reference(set_up_triangles(geometry, params, in->cull_backfaces != 0), params, visibility);
    std::memcpy(out->triangle, visibility.triangle.data(), visibility.size() * sizeof(uint32_t));
    if (barycentrics) {
        std::memcpy(out->barycentrics, visibility.bary.data(), visibility.size() * sizeof(glm::vec3));
        out->barycentrics_written = 1;
    }
    return RASTER_PLUGIN_DRAWN;
}

int draw_with_barycentrics(const raster_plugin_frame* in, raster_plugin_samples* out) { return draw(in, out, true); }
int draw_ids_only(const raster_plugin_frame* in, raster_plugin_samples* out) { return draw(in, out, false); }

}  // namespace

std::shared_ptr<const plugin::PluginLibrary> raster_stages_plugin(bool barycentrics) {
    return std::make_shared<plugin::PluginLibrary>(
        plugin::PluginFunctions{abi_version, name, barycentrics ? draw_with_barycentrics : draw_ids_only},
        "raster_stages_plugin (in process)");
}

}  // namespace raster::properties
