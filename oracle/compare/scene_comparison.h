// One comparison run: renders a scene with raster (possibly with faulty stages) and with the oracle, classes every
// sample, and reports counts, the largest colour error and both renderers' times, as JSON or a human summary.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "oracle/compare/sample_classifier.h"
#include "oracle/reference/ray_caster.h"
#include "raster/image/image.h"
#include "raster/pipeline/stages.h"
#include "raster/pipeline/render.h"
#include "raster/scene/scene.h"

namespace raster::oracle {

struct ComparisonOptions {
    OracleMode mode = OracleMode::robust;
    int threads = 0;  // 0 = all cores, for both renderers and the comparator; results do not depend on it
    RasterPath raster_path = RasterPath::tiled;  // raster's renderer (a mutant of the reference rasterizer: reference)
};

struct Comparison {
    std::string scene;  // the scene file
    int width = 0, height = 0, samples = 0;
    OracleMode mode = OracleMode::robust;
    ComparisonCounts counts;
    int max_color_error = 0;  // 0-255, on agreeing samples
    double raster_ms = 0;     // raster's in-process frame time (RenderStats::ms_total)
    double oracle_ms = 0;     // the oracle's: vertex stage, BVH build, one ray per sample, shading and resolve
    double compare_ms = 0;    // reference geometry and classification
    RenderResult raster;      // raster's visibility buffer and image
    VisibilityBuffer oracle_visibility;
    Image oracle_image;       // the oracle's visibility buffer through the same shader and resolve
    std::vector<SampleClass> classes;  // per sample
};

// Renders and compares. `stages` are raster's (a test passes a mutant's); the oracle always uses the real camera,
// sample positions and shading. The scene must be valid (validate_scene). Throws OracleError if Embree fails.
Comparison compare_scene(const Scene& scene, const ComparisonOptions& options, const PipelineStages& stages = {});

// {scene, width, height, samples, oracle_mode, agree, ambiguous: {edge_band, depth_tie, clip_boundary, facing},
//  ambiguous_total, genuine: {visibility, barycentrics, depth, color}, genuine_total, max_color_error,
//  raster_ms, oracle_ms, compare_ms}
nlohmann::json comparison_json(const Comparison& comparison);

// A few lines for a person: the counts by reason, the colour error and the times.
std::string comparison_summary(const Comparison& comparison);

}  // namespace raster::oracle
