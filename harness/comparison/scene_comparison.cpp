// A comparison run, stage by stage: raster's render job into a temporary folder, the oracle, the sample classes,
// then each file read back and judged; each timed.
#include "harness/comparison/scene_comparison.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <system_error>

#include <unistd.h>

#include "harness/comparison/decoded_image.h"
#include "harness/comparison/oracle_run.h"
#include "harness/comparison/pixel_evidence.h"
#include "oracle/reference/reference_geometry.h"
#include "oracle/reference/sample_positions.h"
#include "oracle/reference/shadow_oracle.h"
#include "raster/core/stopwatch.h"
#include "raster/scene/validation.h"

namespace raster::harness {
namespace {

oracle::RasterPixels pixels_of(const Image& image) {
    return {image.width, image.height, image.channels, image.pixels.data()};
}

// A file's decoded pixels when it holds the channels its format and kind must (a writer that drops or adds a
// channel is wrong at every pixel: the checks take an empty view as such).
oracle::RasterPixels pixels_with_channels(const Image& image, int channels) {
    if (image.channels != channels) return {};
    return pixels_of(image);
}

oracle::RasterSamples samples_of(const VisibilityBuffer& visibility) {
    return {visibility.width,           visibility.height,      visibility.samples,
            visibility.triangle.data(), visibility.bary.data(), visibility.view_depth.data()};
}

// A fresh folder for the comparison's files, removed with them when the comparison ends: in memory (/dev/shm) where
// the system has it, so that the writer's fsync costs nothing, else under the system's temporary folder.
class ScratchFolder {
public:
    ScratchFolder() {
        std::error_code error;
        const std::filesystem::path memory = "/dev/shm";
        const std::filesystem::path parent =
            std::filesystem::is_directory(memory, error) && ::access(memory.c_str(), W_OK) == 0
                ? memory
                : std::filesystem::temp_directory_path();
        std::string pattern = (parent / "raster_compare_XXXXXX").string();
        if (::mkdtemp(pattern.data()) == nullptr)
            throw OutputError("cannot make a temporary folder for the comparison's files under " + parent.string());
        path_ = pattern;
    }
    ~ScratchFolder() {
        std::error_code ignored;
        std::filesystem::remove_all(path_, ignored);
    }
    ScratchFolder(const ScratchFolder&) = delete;
    ScratchFolder& operator=(const ScratchFolder&) = delete;
    const std::filesystem::path& path() const { return path_; }

private:
    std::filesystem::path path_;
};

// The files the job writes for the comparison: each output `raster render` can write, as PNG and as PPM.
struct JudgedFiles {
    std::filesystem::path colour_png, colour_ppm, depth_png, depth_ppm;
};

// Stage 1: `raster render`'s job, into `folder`, with the visibility buffer kept.
JudgedFiles render_raster(const Scene& scene, const ComparisonOptions& options, const std::filesystem::path& folder,
                          Comparison& out) {
    RenderJob job;
    job.options.threads = options.threads;
    job.options.path = options.raster_path;
    job.options.alpha = options.alpha;
    job.keep_visibility = true;
    JudgedFiles files;
    if (options.colour_output) {
        files.colour_png = folder / "colour.png";
        files.colour_ppm = folder / "colour.ppm";
        job.outputs.push_back({files.colour_png, OutputKind::colour});
        job.outputs.push_back({files.colour_ppm, OutputKind::colour});
    }
    if (options.depth_output) {
        files.depth_png = folder / "depth.png";
        files.depth_ppm = folder / "depth.ppm";
        job.outputs.push_back({files.depth_png, OutputKind::depth});
        job.outputs.push_back({files.depth_ppm, OutputKind::depth});
    }
    const RasterRenderer raster_renderer;
    const Renderer& renderer = options.renderer ? *options.renderer : raster_renderer;
    if (!renderer.gives_visibility())
        throw std::invalid_argument(renderer.name() + " gives no per-sample visibility, which a comparison classes");
    RenderedFrame rendered;
    run_render_job(scene, job, renderer, rendered);
    out.renderer = renderer.name();  // after the frame: the GL backend names the implementation it drew on
    out.raster = std::move(rendered.result);
    out.raster_ms = out.raster.stats.ms_total;
    out.write_ms = rendered.ms_write;
    return files;
}

// Stage 5a: the colour files against the bounds, each disagreement told apart as a shadow's or a transparent
// layer's where that is what explains it.
void judge_colour_files(const JudgedFiles& files, const oracle::PixelBounds& bounds, const OracleRun& run,
                        Comparison& out) {
    ColourVerdicts& colour = out.colour;
    colour.written = true;
    colour.png_image = decoded_file(files.colour_png);
    const Image& png = colour.png_image;
    const Image ppm = decoded_file(files.colour_ppm);
    colour.png = oracle::check_colours(bounds, pixels_with_channels(png, bounds.channels), run.image);  // RGB or RGBA
    colour.ppm = oracle::check_colours(bounds, pixels_with_channels(ppm, 3), run.image);  // PPM holds no alpha
    const size_t pixels = colour.png.genuine_pixels.size();
    colour.genuine.resize(pixels);
    ShadowVerdicts& shadows = out.shadows;
    shadows.genuine.resize(pixels);
    for (size_t i = 0; i < pixels; ++i) {
        colour.genuine[i] = colour.png.genuine_pixels[i] | colour.ppm.genuine_pixels[i];
        colour.genuine_pixels += colour.genuine[i];
        // A shadow disagreement when every file that is off is off only by its shadows.
        const bool png_other = colour.png.genuine_pixels[i] && !colour.png.shadow_pixels[i];
        const bool ppm_other = colour.ppm.genuine_pixels[i] && !colour.ppm.shadow_pixels[i];
        // A pixel with transparent layers is a transparency disagreement first: its layers' shading includes the
        // shadows, so leaving shadows open there would excuse a wrong blend as well.
        const bool layered = !bounds.layered.empty() && bounds.layered[i];
        out.transparency.genuine_pixels += colour.genuine[i] && layered;
        shadows.genuine[i] = colour.genuine[i] && !layered && !png_other && !ppm_other;
        shadows.genuine_pixels += shadows.genuine[i];
    }
}

// Stage 5b: what the shadow model and the transparent layers left open, from the bounds.
void tally_open_pixels(const oracle::PixelBounds& bounds, Comparison& out) {
    TransparencyVerdicts& transparency = out.transparency;
    for (size_t pixel = 0; pixel < bounds.layer_open.size(); ++pixel) {
        // Counted where the layers are what leaves the pixel open (not where a sample is genuine anyway).
        const oracle::LayerOpen open = bounds.state[pixel] == oracle::PixelState::ambiguous ? bounds.layer_open[pixel]
                                                                                           : oracle::LayerOpen::none;
        transparency.open.push_back(open != oracle::LayerOpen::none);
        transparency.edge_pixels += open == oracle::LayerOpen::edge;
        transparency.depth_pixels += open == oracle::LayerOpen::depth;
        transparency.order_pixels += open == oracle::LayerOpen::order;
    }
    using oracle::ShadowVerdict;
    ShadowVerdicts& shadows = out.shadows;
    shadows.seen = bounds.shadow_seen;
    for (uint8_t seen : bounds.shadow_seen) {
        shadows.edge_pixels += (seen >> static_cast<int>(ShadowVerdict::open_edge)) & 1u;
        shadows.depth_pixels += (seen >> static_cast<int>(ShadowVerdict::open_depth)) & 1u;
        shadows.inconsistent_pixels += (seen >> static_cast<int>(ShadowVerdict::inconsistent)) & 1u;
    }
}

// Stage 5c: the depth files against the depth image's definition over raster's samples.
void judge_depth_files(const JudgedFiles& files, Comparison& out) {
    DepthVerdicts& depth = out.depth;
    depth.written = true;
    const oracle::RasterSamples samples = samples_of(out.raster.visibility);
    depth.png = oracle::check_depth_image(samples, pixels_with_channels(decoded_file(files.depth_png), 1));  // grey
    depth.ppm = oracle::check_depth_image(samples, pixels_with_channels(decoded_file(files.depth_ppm), 1));
    for (size_t i = 0; i < depth.png.genuine_pixels.size(); ++i)
        depth.genuine_pixels += depth.png.genuine_pixels[i] | depth.ppm.genuine_pixels[i];
}

}  // namespace

uint64_t comparison_bytes(const RenderSettings& settings) {
    const uint64_t pixels = uint64_t(std::max(settings.width, 0)) * uint64_t(std::max(settings.height, 0));
    return frame_bytes(settings) + pixels * uint64_t(std::max(settings.samples, 0)) * 21u + pixels * 50u;
}

std::string comparison_problem(const Scene& scene) {
    const RenderSettings& settings = scene.settings;
    if (settings.resolution_divisor > 1)
        return "a frame at resolution divisor " + std::to_string(settings.resolution_divisor) +
               " is not compared: the oracle judges frames sample by sample at their own size, and this one's "
               "samples are not the image's; `raster tradeoff` measures it against the 64-sample reference";
    const uint64_t bytes = comparison_bytes(settings);
    if (bytes <= kMaxFrameBytes) return "";
    return "comparing a " + std::to_string(settings.width) + "x" + std::to_string(settings.height) + " image with " +
           std::to_string(settings.samples) + " samples needs " + std::to_string(bytes >> 20) + " MiB, over the " +
           std::to_string(kMaxFrameBytes >> 20) + " MiB cap";
}

Comparison compare_scene(const Scene& scene, const ComparisonOptions& options) {
    Comparison out;
    out.scene = scene.path;
    out.width = scene.settings.width;
    out.height = scene.settings.height;
    out.samples = scene.settings.samples;
    out.mode = options.mode;
    out.judged = judged_classes(scene.settings.modes);

    const ScratchFolder folder;
    const JudgedFiles files = render_raster(scene, options, folder.path(), out);

    auto start = Clock::now();
    const OracleRun run = run_oracle(scene, {options.mode, options.threads, options.alpha}, out.oracle_visibility);
    out.oracle_image = image_of(run.image);
    out.oracle_ms = milliseconds_since(start);

    start = Clock::now();
    // Stage 3: every sample of raster's frame against the oracle's.
    const oracle::ReferenceGeometry reference(scene, run.geometry);
    const std::vector<glm::dvec2> offsets =
        oracle::sample_offsets_on_grid(scene.settings.samples, scene.settings.pattern, scene.settings.snap_bits);
    oracle::CompareInputs inputs;
    inputs.raster = samples_of(out.raster.visibility);
    inputs.oracle = &out.oracle_visibility;
    inputs.reference = &reference;
    inputs.offsets = offsets;
    inputs.threads = options.threads;
    out.visibility = oracle::compare_visibility(inputs);

    // Stage 4: the colour bounds every judged pixel must lie in.
    const oracle::PixelBounds bounds =
        colour_bounds(scene, run, reference, offsets, out.oracle_visibility, out.visibility.classes, options.threads);
    if (options.colour_output) judge_colour_files(files, bounds, run, out);
    tally_open_pixels(bounds, out);
    if (options.depth_output) judge_depth_files(files, out);
    if (options.evidence_pixels > 0)
        out.evidence = pixel_evidence({&out, &reference, &offsets, &bounds, options.evidence_pixels});
    out.compare_ms = milliseconds_since(start);
    return out;
}

}  // namespace raster::harness
