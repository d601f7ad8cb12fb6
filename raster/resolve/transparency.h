// Transparency: the pass that blends the surfaces whose material opacity is below 1 over the opaque frame
// (docs/transparency.md). The opaque surfaces are rasterized and resolved first, as in any frame; then every
// transparent fragment in front of a sample's opaque surface is kept (an A-buffer, `sorted`) or accumulated
// (`weighted`), and only the pixels some transparent fragment reaches are resolved again.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "raster/image/image.h"
#include "raster/geometry/frame_params.h"
#include "raster/resolve/resolve.h"
#include "raster/geometry/setup.h"
#include "raster/shading/shade.h"
#include "raster/rasterize/visibility_buffer.h"
#include "raster/scene/scene.h"

namespace raster {

struct TransparencyInputs {
    const std::vector<TriangleSetup>* setups = nullptr;  // the transparent ones, in draw order
    const FrameParams* frame = nullptr;
    const VisibilityBuffer* opaque = nullptr;  // the opaque surfaces' samples (every sample written)
    const Shader* shader = nullptr;
    ResolveParams resolve;
    TransparencySettings settings;
};

// Blends the transparent setups over the opaque frame in `image` (already resolved from `opaque`), rewriting the
// pixels a transparent fragment reaches. A fragment counts at a sample its setup covers (the rasterizer's coverage
// test) where its view depth is below the opaque surface's, or where there is none. Its opacity a is the shader's
// at the fragment (its material's, times its texture's alpha, or a cut-out's 0 or 1). Per sample, front to back:
//   sorted:   C = sum_i T_i a_i c_i, T_i = prod_{j<i} (1 - a_j), over the fragments sorted by view depth (ties in
//             draw order); then C += T c_opaque (T the product over all), and the sample's alpha is 1 with an
//             opaque surface, 1 - T without.
//   weighted: C = (sum a_i c_i / sum a_i) (1 - T) + T c_opaque, the same T: any order, no lists.
// The pixel is the mean of C + (1 - alpha) background over its samples, or with RGBA output the mean of C over
// the mean alpha, and the mean alpha. MSAA shades each triangle once per pixel, colour and opacity, at the first of
// the pixel's samples in pattern order where it is kept. Returns the number of fragments kept.
// Throws InputError when `sorted` would keep more than settings.max_fragments fragments in the frame (counted per
// setup and band, so the pass stops within one setup's share of a band past the cap).
size_t composite_transparency(const TransparencyInputs& inputs, Image& image);

}  // namespace raster
