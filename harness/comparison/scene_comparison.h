// One comparison run: a scene through exactly the path `raster render` runs (the tiled renderer, SIMD and
// hierarchical Z as the scene and options say, its visibility buffer kept) and through the independent oracle;
// every sample classed, and raster's image, as its PNG and its PPM writer encode it, checked pixel by pixel
// against the oracle's colour bounds. Counts, times, JSON and a summary.
#pragma once

#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

#include "oracle/compare/colour_check.h"
#include "oracle/compare/sample_classifier.h"
#include "oracle/reference/ray_caster.h"
#include "raster/image/image.h"
#include "raster/frame/render.h"
#include "raster/scene/scene.h"

namespace raster::harness {

struct ComparisonOptions {
    oracle::OracleMode mode = oracle::OracleMode::robust;
    int threads = 0;  // 0 = all cores, for both renderers and the comparator; results do not depend on it
    RasterPath raster_path = RasterPath::tiled;  // raster's renderer (a mutant of the reference rasterizer: reference)
    bool alpha = false;                          // `raster render --alpha`: RGBA, alpha = coverage
};

struct Comparison {
    std::string scene;  // the scene file
    int width = 0, height = 0, samples = 0;
    oracle::OracleMode mode = oracle::OracleMode::robust;
    RenderResult raster;                      // raster's visibility buffer and image
    oracle::SampleBuffer oracle_visibility;   // the oracle's
    Image oracle_image;                       // the oracle's own colours at its hits, resolved
    oracle::VisibilityComparison visibility;  // per sample
    oracle::ColourCheck png, ppm;             // per pixel, raster's image decoded from each file format
    std::vector<uint8_t> colour_genuine;      // per pixel: outside its bounds in either file
    uint64_t colour_genuine_pixels = 0;       // how many
    // With lights that cast shadows: of those, how many are explained by a shadow test (inside the bounds once the
    // shadows are left open: acne, light leaking, a wrong map); and how many judged pixels the shadow model left
    // open by an occluder's edge in the footprint, by a surface within the bias, or by the oracle's ray and exact
    // footprint disagreeing (never expected).
    std::vector<uint8_t> shadow_genuine;      // per pixel
    std::vector<uint8_t> shadow_seen;         // per judged pixel: the shadow verdicts met (ShadowTally bits)
    uint64_t shadow_genuine_pixels = 0;
    uint64_t shadow_edge_pixels = 0, shadow_depth_pixels = 0, shadow_inconsistent_pixels = 0;
    // With transparency: of the genuine colour pixels, how many composite transparent layers (never counted as a
    // shadow's);
    // and how many pixels the layers left open (ambiguous) by a layer's edge, a layer's depth against the opaque
    // surface's, or two layers' order.
    uint64_t transparency_genuine_pixels = 0;
    std::vector<uint8_t> layers_open;  // per pixel: 1 where the layers leave it open; empty without transparency
    uint64_t transparency_edge_pixels = 0, transparency_depth_pixels = 0, transparency_order_pixels = 0;
    double raster_ms = 0;   // raster's in-process frame time (RenderStats::ms_total)
    double oracle_ms = 0;   // the oracle: geometry, BVH build, one ray per sample, shading and resolve
    double compare_ms = 0;  // reference geometry, classification, colour bounds and checks

    // Genuine samples plus pixels of genuine colour: 0 means raster agrees with the oracle.
    uint64_t genuine_total() const { return visibility.counts.genuine_total() + colour_genuine_pixels; }
};

// Bytes a comparison of a frame with `settings` holds at once: raster's frame buffers (scene/validation.h's 28 per
// sample), the oracle's sample buffer (20) and the classes (1) per sample; per pixel the images, the decoded files
// and the colour bounds (about 50). compare_scene refuses frames above kMaxFrameBytes (comparison_problem).
uint64_t comparison_bytes(const RenderSettings& settings);
// Empty when a comparison of the scene fits the cap, else what is wrong.
std::string comparison_problem(const Scene& scene);

// Renders and compares. The scene must be valid (scene/validation.h) and fit the comparison's memory cap
// (comparison_problem). Throws OracleError if Embree fails.
Comparison compare_scene(const Scene& scene, const ComparisonOptions& options);

// {scene, width, height, samples, oracle_mode, agree, ambiguous: {edge_band, depth_tie, clip_boundary, facing},
//  ambiguous_total, ambiguous_fraction: {...}, genuine: {visibility, barycentrics, depth, color, shadow},
//  genuine_total, shadows: {edge, depth, inconsistent} (pixels, with lights that cast shadows),
//  pixels: {judged, ambiguous, color_png, color_ppm}, max_color_error, color_disagreements: [...],
//  raster_ms, oracle_ms, compare_ms}
nlohmann::json comparison_json(const Comparison& comparison);

// A few lines for a person: the counts by reason, the colour check and the times.
std::string comparison_summary(const Comparison& comparison);

// The genuine counts by reason, "visibility 12, color 3", or "-" when there are none.
std::string genuine_reasons(const Comparison& comparison);

// The first `shown` genuine samples (where, and what each renderer saw there) and colour disagreements (the
// bytes, the allowed ranges and the oracle's), one per line, for a failure message.
std::string genuine_details(const Comparison& comparison, int shown = 8);

// The comparison's disagreement map (oracle/compare/diff_map.h) over raster's image.
Image diff_map(const Comparison& comparison);

}  // namespace raster::harness
