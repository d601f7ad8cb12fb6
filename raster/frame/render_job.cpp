// The render job: frames on the renderer, then each output encoded and written whole.
#include "raster/frame/render_job.h"

#include <algorithm>

#include "raster/core/errors.h"
#include "raster/core/stopwatch.h"
#include "raster/image/image.h"
#include "raster/resolve/depth_image.h"

namespace raster {

void run_render_job(const Scene& scene, const RenderJob& job, const Renderer& renderer, RenderedFrame& out) {
    const bool depth = std::any_of(job.outputs.begin(), job.outputs.end(),
                                   [](const FrameOutput& o) { return o.kind == OutputKind::depth; });
    if (depth && !renderer.gives_visibility())
        throw std::invalid_argument(renderer.name() + " gives no visibility buffer, so no depth image");
    if (depth && scene.settings.resolution_divisor > 1)
        throw InputError("no depth image at resolution divisor " + std::to_string(scene.settings.resolution_divisor) +
                         ": the depth buffer is the internal frame's, smaller than the image");
    if (job.options.alpha && scene.settings.resolution_divisor > 1)
        throw InputError("no alpha at resolution divisor " + std::to_string(scene.settings.resolution_divisor) +
                         ": the stretch blends each channel alone, so an uncovered pixel's background colour would "
                         "bleed into its covered neighbours' RGB");
    RenderOptions options = job.options;
    options.keep_visibility = depth || job.keep_visibility;  // the full-frame sample planes, only if read
    out.frame_ms.clear();
    for (int frame = 0; frame < job.repeat; ++frame) {
        renderer.render_into(scene, options, out.result);
        out.frame_ms.push_back(out.result.stats.ms_total);
    }
    const auto write_start = Clock::now();
    Image depth_pixels;
    if (depth) depth_pixels = depth_image(out.result.visibility);
    for (const FrameOutput& output : job.outputs) {
        try {
            write_image(output.path, output.kind == OutputKind::depth ? depth_pixels : out.result.image,
                        options.threads);
        } catch (const std::exception& error) {
            throw OutputError(error.what());
        }
    }
    out.ms_write = milliseconds_since(write_start);
}

}  // namespace raster
