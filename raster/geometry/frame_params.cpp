// The frame's parameters: the derived values (fixed bits, fixed-point offsets, their extent) computed once.
#include "raster/geometry/frame_params.h"

#include <algorithm>
#include <utility>

namespace raster {
namespace {

// Fills the values derived from the image size, snap bits and sample offsets.
void derive(FrameParams& frame) {
    frame.fixed_bits = fixed_bits_for(frame.snap_bits);
    frame.fixed_offsets = fixed_sample_offsets(frame.sample_offsets, frame.fixed_bits);
    const auto& x = frame.fixed_offsets.x;
    const auto& y = frame.fixed_offsets.y;
    if (x.empty()) return;
    frame.extent = {*std::min_element(x.begin(), x.end()), *std::max_element(x.begin(), x.end()),
                    *std::min_element(y.begin(), y.end()), *std::max_element(y.begin(), y.end())};
}

// The side planes' factor: 1 for full clipping, the guard band's for guard-band clipping (conventions.h).
double side_factor(const RenderSettings& settings) {
    if (settings.modes.clipping != Clipping::guard_band) return 1.0;
    return guard_band_factor(settings.width, settings.height, fixed_bits_for(settings.snap_bits));
}

}  // namespace

FrameParams frame_params_for(const Scene& scene, std::vector<glm::vec2> sample_offsets, int threads) {
    const RenderSettings& settings = scene.settings;
    FrameParams frame;
    frame.width = settings.width;
    frame.height = settings.height;
    frame.snap_bits = settings.snap_bits;
    frame.clip = ClipVolume{scene.camera.near, scene.camera.far, side_factor(settings),
                            scene.camera.projection == Projection::orthographic};
    frame.edges = settings.modes.edges;
    frame.interpolation = settings.modes.interpolation;
    frame.depth = settings.modes.depth;
    frame.hierarchical_z = settings.modes.hierarchical_z;
    frame.sample_offsets = std::move(sample_offsets);
    frame.threads = threads;
    derive(frame);
    return frame;
}

FrameParams frame_params(int width, int height, int snap_bits, std::vector<glm::vec2> sample_offsets) {
    FrameParams frame;
    frame.width = width;
    frame.height = height;
    frame.snap_bits = snap_bits;
    const Camera camera;
    frame.clip = ClipVolume{camera.near, camera.far, 1.0};
    frame.sample_offsets = std::move(sample_offsets);
    derive(frame);
    return frame;
}

}  // namespace raster
