// Running stages on hand-made frames and triangles, rasterized on the implementation's backend (its thread count
// is fixed, and every backend gives the same bytes for any thread count, so results are reproducible).
#include "properties/stage_driver.h"

#include <bit>

#include <rapidcheck.h>

#include "backends/plugin/plugin_renderer.h"
#include "raster/frame/shadow_pass.h"
#include "raster/rasterize/tile_rasterizer.h"

#include "properties/reference/documented_samples.h"
#include "properties/printing.h"

namespace raster::properties {

int Frame::exact_bits() const {
    const int largest = width > height ? width : height;
    return 25 - std::bit_width(static_cast<unsigned>(largest - 1));  // 25 - log2(largest) for powers of two
}

std::ostream& operator<<(std::ostream& os, const Frame& f) {
    return os << "Frame{" << f.width << ", " << f.height << ", " << f.samples << ", SamplePattern::"
              << to_string(f.pattern) << ", " << f.snap_bits << ", {" << float_literal(f.volume.near) << ", "
              << float_literal(f.volume.far) << "}}";
}

std::ostream& operator<<(std::ostream& os, const ClipTriangle& t) {
    return os << "ClipTriangle{{" << literal(t.v[0]) << ", " << literal(t.v[1]) << ", " << literal(t.v[2]) << "}}";
}

glm::vec4 clip_from_screen(const Frame& frame, const glm::dvec2& screen, float w, float depth) {
    const glm::dvec2 ndc = ndc_of_screen(frame, screen);
    const float x = static_cast<float>(ndc.x), y = static_cast<float>(ndc.y);
    return {x * w, y * w, depth * w, w};
}

glm::dvec2 ndc_of(const glm::dvec4& clip) { return {clip.x / clip.w, clip.y / clip.w}; }

glm::dvec2 screen_of_ndc(const Frame& frame, const glm::dvec2& ndc) {
    return {(ndc.x + 1.0) * 0.5 * frame.width, (1.0 - ndc.y) * 0.5 * frame.height};
}

glm::dvec2 ndc_of_screen(const Frame& frame, const glm::dvec2& screen) {
    return {2.0 * screen.x / frame.width - 1.0, 1.0 - 2.0 * screen.y / frame.height};
}

std::string describe(const Sample& s) {
    return "sample " + std::to_string(s.s) + " of pixel (" + std::to_string(s.x) + ", " + std::to_string(s.y) + ")";
}

std::vector<Sample> samples_of(const Frame& frame) {
    const int fixed_bits = frame.fixed_bits();
    const std::vector<reference::Point> offsets = documented_fixed_offsets(frame.samples, frame.pattern, fixed_bits);
    const double unit = std::ldexp(1.0, -fixed_bits);
    std::vector<Sample> samples;
    samples.reserve(static_cast<size_t>(frame.width) * frame.height * offsets.size());
    for (int y = 0; y < frame.height; ++y)
        for (int x = 0; x < frame.width; ++x)
            for (int s = 0; s < static_cast<int>(offsets.size()); ++s) {
                Sample sample;
                sample.x = x;
                sample.y = y;
                sample.s = s;
                sample.index = samples.size();
                sample.fixed = {(int64_t{x} << fixed_bits) + offsets[s].x, (int64_t{y} << fixed_bits) + offsets[s].y};
                sample.screen = {static_cast<double>(sample.fixed.x) * unit, static_cast<double>(sample.fixed.y) * unit};
                samples.push_back(sample);
            }
    return samples;
}

reference::Point snapped(const Frame& frame, const glm::vec4& clip) {
    return reference::snapped_vertex(clip, frame.width, frame.height, frame.snap_bits);
}

namespace {
thread_local size_t rasterizer_run_count = 0;

// The plugin draws whole frames only: raster's stages run on a plugin backend would check raster, not the plugin.
void refuse_plugin(const Implementation& impl, const char* entry) {
    if (impl.backend.plugin)
        throw std::logic_error(std::string("a property run on the plugin backend called ") + entry +
                               ", raster's own stages: only whole frames (draw, coverage_counts, render_with) reach "
                               "a plugin, so register it with RASTER_DRAWING_PROPERTY, not RASTER_RENDERER_PROPERTY");
}

// The triangles as one frame for the plugin: the frame's size, its sample positions by the implementation's
// sample_offsets stage, its sub-pixel bits and view volume; no culling.
VisibilityBuffer draw_on_plugin(const Implementation& impl, const Frame& frame,
                                const std::vector<ClipTriangle>& triangles) {
    plugin::ClipSpaceFrame request;
    request.width = frame.width;
    request.height = frame.height;
    request.sample_offsets = impl.stages.sample_offsets(frame.samples, frame.pattern);
    request.subpixel_bits = frame.snap_bits;
    request.orthographic = frame.volume.orthographic;
    request.near_plane = frame.volume.near;
    request.far_plane = frame.volume.far;
    for (const ClipTriangle& t : triangles) request.triangles.push_back(t.v);
    VisibilityBuffer visibility;
    try {
        impl.backend.plugin->draw(request, visibility);
    } catch (const plugin::PluginRefusal& refusal) {  // a frame the plugin does not draw is no case for it
        RC_DISCARD(refusal.what());
    }
    return visibility;
}
}  // namespace

std::vector<TriangleSetup> set_up(const Implementation& impl, const Frame& frame,
                                  const std::vector<ClipTriangle>& triangles) {
    refuse_plugin(impl, "set_up");
    std::vector<TriangleSetup> setups;
    FrameParams params = frame_params(frame.width, frame.height, frame.snap_bits);
    params.clip = frame.volume;
    for (size_t i = 0; i < triangles.size(); ++i) {
        const ClipTriangle& t = triangles[i];
        const ClippedPolygon polygon = impl.stages.clip(t.v[0], t.v[1], t.v[2], frame.volume);
        impl.stages.setup(polygon, static_cast<uint32_t>(i), params, setups);
    }
    return setups;
}


size_t rasterizer_runs() { return rasterizer_run_count; }

VisibilityBuffer rasterize_setups(const Implementation& impl, const Frame& frame,
                                  const std::vector<TriangleSetup>& setups) {
    refuse_plugin(impl, "rasterize_setups");
    FrameParams params =
        frame_params(frame.width, frame.height, frame.snap_bits, impl.stages.sample_offsets(frame.samples, frame.pattern));
    params.threads = impl.backend.threads;
    params.hierarchical_z = impl.backend.hierarchical_z;
    ++rasterizer_run_count;
    VisibilityBuffer visibility;
    if (impl.backend.path == RasterPath::reference) impl.stages.reference_rasterize(setups, params, visibility);
    else rasterize_tiled(setups, params, impl.backend.allow_simd, visibility);
    return visibility;
}

VisibilityBuffer draw(const Implementation& impl, const Frame& frame, const std::vector<ClipTriangle>& triangles) {
    if (impl.backend.plugin) {
        ++rasterizer_run_count;
        return draw_on_plugin(impl, frame, triangles);
    }
    return rasterize_setups(impl, frame, set_up(impl, frame, triangles));
}

std::vector<int> coverage_counts(const Implementation& impl, const Frame& frame,
                                 const std::vector<ClipTriangle>& triangles) {
    std::vector<int> counts(static_cast<size_t>(frame.width) * frame.height * frame.samples, 0);
    for (const ClipTriangle& triangle : triangles) {
        const VisibilityBuffer visibility = draw(impl, frame, {triangle});
        for (size_t i = 0; i < visibility.size() && i < counts.size(); ++i)
            counts[i] += visibility.triangle[i] != kNoTriangle;
    }
    return counts;
}

ShadowMaps shadow_maps_with(const Implementation& impl, const Scene& scene, const std::vector<glm::vec3>& world_positions) {
    refuse_plugin(impl, "shadow_maps_with");
    ++rasterizer_run_count;
    return render_shadow_maps(scene, world_positions, raster_backend(impl.backend.path, impl.backend.allow_simd),
                              impl.backend.threads);
}

RenderResult render_with(const Implementation& impl, const Scene& scene) {
    RenderOptions options;
    options.threads = impl.backend.threads;
    options.path = impl.backend.path;
    options.allow_simd = impl.backend.allow_simd;
    ++rasterizer_run_count;
    if (impl.backend.plugin) {
        RenderResult result;
        try {
            plugin::PluginRenderer(impl.backend.plugin).render_into(scene, options, result);
        } catch (const plugin::PluginRefusal& refusal) {
            RC_DISCARD(refusal.what());
        }
        return result;
    }
    if (scene.settings.modes.hierarchical_z == impl.backend.hierarchical_z) return render(scene, options);
    Scene configured = scene;
    configured.settings.modes.hierarchical_z = impl.backend.hierarchical_z;
    return render(configured, options);
}

}  // namespace raster::properties
