// What one comparison run holds: raster's frame and the oracle's, every sample's class, and each file's verdicts
// (colour, shadows, transparency, depth), with the times; plain data, filled in by compare_scene (scene_comparison.h).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/comparison/judged_classes.h"
#include "oracle/compare/colour_check.h"
#include "oracle/compare/depth_image_check.h"
#include "oracle/compare/sample_classifier.h"
#include "oracle/reference/ray_caster.h"
#include "raster/frame/renderer.h"
#include "raster/image/image.h"

namespace raster::harness {

// The colour image's verdicts, per file format.
struct ColourVerdicts {
    bool written = false;
    oracle::ColourCheck png, ppm;     // per pixel, the file decoded
    Image png_image;                  // the PNG file as decoded: the bytes judged
    std::vector<uint8_t> genuine;     // per pixel: outside its bounds in either file
    uint64_t genuine_pixels = 0;      // how many (of them shadow and transparency ones, below)
};

// With lights that cast shadows: of the genuine colour pixels, how many are explained by a shadow test (inside the
// bounds once the shadows are left open: acne, light leaking, a wrong map); and how many judged pixels the shadow
// model left open by an occluder's edge in the footprint, by a surface within the bias, or by the oracle's ray and
// exact footprint disagreeing (never expected).
struct ShadowVerdicts {
    std::vector<uint8_t> genuine;  // per pixel
    std::vector<uint8_t> seen;     // per judged pixel: the shadow verdicts met (ShadowTally bits)
    uint64_t genuine_pixels = 0;
    uint64_t edge_pixels = 0, depth_pixels = 0, inconsistent_pixels = 0;
};

// With transparency: of the genuine colour pixels, how many composite transparent layers (never counted as a
// shadow's); and how many pixels the layers left open (ambiguous) by a layer's edge, a layer's depth against the
// opaque surface's, or two layers' order.
struct TransparencyVerdicts {
    std::vector<uint8_t> open;  // per pixel: 1 where the layers leave it open; empty without transparency
    uint64_t genuine_pixels = 0;
    uint64_t edge_pixels = 0, depth_pixels = 0, order_pixels = 0;
};

// The depth image's verdicts, per file format.
struct DepthVerdicts {
    bool written = false;
    oracle::DepthImageCheck png, ppm;
    uint64_t genuine_pixels = 0;  // pixels wrong in either file
};

struct Comparison {
    std::string scene;  // the scene file
    std::string renderer;
    int width = 0, height = 0, samples = 0;
    oracle::OracleMode mode = oracle::OracleMode::robust;
    RenderResult raster;                      // the frame the job wrote: its visibility buffer and image
    oracle::SampleBuffer oracle_visibility;   // the oracle's
    Image oracle_image;                       // the oracle's own colours at its hits, resolved
    oracle::VisibilityComparison visibility;  // per sample
    ColourVerdicts colour;
    ShadowVerdicts shadows;
    TransparencyVerdicts transparency;
    DepthVerdicts depth;
    JudgedClasses judged;  // what the frame's precision modes let the oracle judge
    nlohmann::json evidence;  // pixel_evidence's, when ComparisonOptions::evidence_pixels asked for it; else null
    double raster_ms = 0;   // raster's in-process frame time (RenderStats::ms_total)
    double write_ms = 0;    // the job's encoding and writing
    double oracle_ms = 0;   // the oracle: geometry, BVH build, one ray per sample, shading and resolve
    double compare_ms = 0;  // reading the files back, reference geometry, classification, colour bounds and checks

    // Genuine samples plus pixels of genuine colour or depth, of the classes the precision modes let the oracle
    // judge: 0 means raster agrees with the oracle. The depth image is judged over raster's own samples, exactly,
    // whatever the modes.
    uint64_t genuine_total() const {
        using oracle::SampleClass;
        uint64_t total = depth.genuine_pixels;
        if (judged.visibility) total += visibility.counts.count(SampleClass::visibility);
        if (judged.interpolation)
            total += visibility.counts.count(SampleClass::barycentrics) + visibility.counts.count(SampleClass::depth) +
                     colour.genuine_pixels;
        return total;
    }
    // Every disagreement, judged or not (what the trade-off table measures a mode's accuracy by).
    uint64_t disagreements_total() const {
        return visibility.counts.genuine_total() + colour.genuine_pixels + depth.genuine_pixels;
    }
};

}  // namespace raster::harness
