// The oracle's own image: every pixel of its visibility buffer resolved with its shading at its own hits, and
// turned into bytes as docs/conventions.md says (clamp to [0, 1], times 255, rounded half up).
#pragma once

#include <cstdint>
#include <vector>

#include "oracle/reference/layer_caster.h"
#include "oracle/reference/layer_resolve.h"
#include "oracle/reference/pixel_resolve.h"
#include "oracle/reference/sample_buffer.h"
#include "oracle/reference/shader.h"

namespace raster::oracle {

struct OracleImage {
    int width = 0, height = 0, channels = 3;
    std::vector<uint8_t> pixels;  // row-major, top row first
};

// With `layers` (a scene with transparency), each sample's hits nearer than its opaque surface are composited
// over it in `mode` (layer_resolve.h). Deterministic for any thread count.
OracleImage render_image(const OracleShader& shader, const SampleBuffer& visibility, const ResolveSettings& settings,
                         int threads, const SampleLayers* layers = nullptr,
                         TransparencyMode mode = TransparencyMode::sorted);

}  // namespace raster::oracle
