// One comparison run: a scene rendered once by exactly the job `raster render` runs (the renderer, its options and
// its file writers), into a temporary folder, with its visibility buffer kept; the independent oracle on the same
// scene; every sample classed, and every file the job wrote read back and judged pixel by pixel: the colour image
// (as PNG and as PPM) against the oracle's colour bounds, the depth image against its definition.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "harness/comparison/comparison.h"
#include "oracle/reference/ray_caster.h"
#include "raster/frame/render_job.h"
#include "raster/frame/renderer.h"
#include "raster/image/image.h"
#include "raster/scene/scene.h"

namespace raster::harness {

struct ComparisonOptions {
    oracle::OracleMode mode = oracle::OracleMode::robust;
    int threads = 0;  // 0 = all cores, for the render job, its writers and the comparator; results do not depend on it
    RasterPath raster_path = RasterPath::tiled;  // raster's backend (a mutant of the reference rasterizer: reference)
    bool alpha = false;                          // `raster render --alpha`: RGBA, alpha = coverage
    // The outputs `raster render` can write for the scene, each written as PNG and as PPM and judged: the colour
    // image (not for a seed 000 shading-depth config, whose task writes the depth image instead) and the depth image
    // (`--depth-out`, or that task).
    bool colour_output = true;
    bool depth_output = true;
    const Renderer* renderer = nullptr;  // what renders the frame: null for raster's own (RasterRenderer)
    // The report's pixel inspector: the evidence of at most this many pixels (pixel_evidence.h) kept in
    // Comparison::evidence; 0 builds none.
    size_t evidence_pixels = 0;
};

// Bytes a comparison of a frame with `settings` holds at once: raster's frame buffers (scene/validation.h's 28 per
// sample), the oracle's sample buffer (20) and the classes (1) per sample; per pixel the images, the decoded files
// and the colour bounds (about 50). compare_scene refuses frames above kMaxFrameBytes (comparison_problem).
uint64_t comparison_bytes(const RenderSettings& settings);
// Empty when a comparison of the scene fits the cap and its frame is at resolution divisor 1, else what is wrong.
std::string comparison_problem(const Scene& scene);

// Renders and compares. The scene must be valid (scene/validation.h) and fit the comparison's memory cap
// (comparison_problem). Throws OracleError if Embree fails, InputError from the renderer, OutputError when the
// temporary folder cannot be written, and std::invalid_argument for a renderer that gives no visibility buffer.
Comparison compare_scene(const Scene& scene, const ComparisonOptions& options);

}  // namespace raster::harness
