// A render job: what `raster render` does once the scene is loaded, and what `raster compare` runs unchanged into a
// temporary folder: frames rendered on a renderer, the last written whole to every output, colour or depth.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <vector>

#include "raster/frame/frame.h"
#include "raster/frame/renderer.h"
#include "raster/scene/scene.h"

namespace raster {

enum class OutputKind {
    colour,  // the frame's image (RGB, or RGBA with options.alpha)
    depth,   // the depth image (resolve/depth_image.h), from the frame's visibility buffer
};

// One file the job writes; its extension picks the format (image.h: ".ppm" PPM, anything else PNG).
struct FrameOutput {
    std::filesystem::path path;
    OutputKind kind = OutputKind::colour;
};

struct RenderJob {
    RenderOptions options;             // options.keep_visibility is set by the job: see keep_visibility
    std::vector<FrameOutput> outputs;  // written in this order
    int repeat = 1;                    // frames rendered, each reusing the previous one's buffers; the last is written
    bool keep_visibility = false;      // keep the visibility buffer even when no output needs it (a comparison)
};

struct RenderedFrame {
    RenderResult result;           // the last frame
    std::vector<double> frame_ms;  // each frame's ms_total
    double ms_write = 0;           // encoding and writing the outputs
};

// An output could not be written; what() names the file and the reason.
class OutputError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Renders job.repeat frames of the valid scene on `renderer`, keeping the visibility buffer when a depth output or
// job.keep_visibility needs it, then writes every output of the last frame in order, each whole (temp file and
// rename), its encoding on job.options.threads threads. Throws OutputError when an output cannot be written (the
// outputs before it stay written), InputError from the renderer or for a depth output or alpha at a
// resolution divisor above 1, and std::invalid_argument when a depth output is asked of a renderer that gives no visibility buffer.
void run_render_job(const Scene& scene, const RenderJob& job, const Renderer& renderer, RenderedFrame& out);

}  // namespace raster
