// The oracle's side of a check: its own frame of the scene (visibility at every sample, shadows, transparent layers,
// shading, the resolved image), and the colour bounds a frame's pixels must lie in, given each sample's class. Shared
// by the comparison (raster's frame, sample by sample) and the grader (any rasterizer's image).
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include <glm/vec2.hpp>

#include "oracle/compare/colour_check.h"
#include "oracle/compare/sample_classifier.h"
#include "oracle/reference/layer_caster.h"
#include "oracle/reference/oracle_image.h"
#include "oracle/reference/pixel_resolve.h"
#include "oracle/reference/ray_caster.h"
#include "oracle/reference/reference_geometry.h"
#include "oracle/reference/scene_geometry.h"
#include "oracle/reference/shader.h"
#include "oracle/reference/shadow_oracle.h"
#include "raster/scene/scene.h"

namespace raster::harness {

struct OracleRunOptions {
    oracle::OracleMode mode = oracle::OracleMode::robust;
    int threads = 0;
    bool alpha = false;  // the image is RGBA, alpha = coverage
};

// What the oracle derives of the scene, kept for the checks.
struct OracleRun {
    oracle::OracleScene geometry;
    std::unique_ptr<oracle::ShadowOracle> shadows;  // with lights that cast shadows, in a shaded frame
    std::unique_ptr<oracle::OracleShader> shader;   // ShadowAnswer::exact
    oracle::ResolveSettings resolve;
    oracle::SampleLayers layers;
    oracle::OracleImage image;
    bool transparent = false;
};

// The oracle's own frame of `scene` (valid); its visibility at every sample goes into `visibility`.
OracleRun run_oracle(const Scene& scene, const OracleRunOptions& options, oracle::SampleBuffer& visibility);

// The bytes each pixel may hold, for the pixels whose samples are all of class agree in `classes` (one per sample,
// in visibility-buffer order); `visibility` is run_oracle's.
oracle::PixelBounds colour_bounds(const Scene& scene, const OracleRun& run, const oracle::ReferenceGeometry& reference,
                                  const std::vector<glm::dvec2>& offsets, const oracle::SampleBuffer& visibility,
                                  const std::vector<oracle::SampleClass>& classes, int threads);

}  // namespace raster::harness
