// The seam between a frame's order (render.h) and the rasterizer that draws it: the tiled production renderer or
// the reference full-frame one, each drawing the opaque frame (coverage, depth, shading, resolve) and depth-only
// passes (the shadow maps' faces). The frame's order, its front end, shadow pass and transparency pass are the same
// code whichever backend draws; a test may hand render_frame a backend of its own.
#pragma once

#include <cstddef>

#include "raster/frame/frame.h"
#include "raster/geometry/frame_params.h"

namespace raster {

class PixelResolver;     // resolve.h
struct TransformedScene;  // vertex_stage.h

// What the frame asks of the opaque draw.
struct OpaqueDraw {
    const FrameParams& frame;
    const PixelResolver& resolver;  // shades and resolves a pixel from its samples
    bool keep_visibility;           // every sample into result.visibility (else the backend may leave it empty)
    // The vertex stage's clip-space triangles, for a backend that runs a front end of its own (a plugin's) in
    // place of the setups; raster's backends draw the setups.
    const TransformedScene* geometry = nullptr;
};

// What the opaque draw reports for the frame's statistics.
struct OpaqueDrawStats {
    size_t covered_samples = 0;
    size_t hidden_blocks = 0;  // (triangle, 8x8 block) pairs hierarchical Z skipped
    double ms_bin = 0;         // the backend's part of setup (the tiled renderer's binning)
    double ms_raster = 0, ms_shade = 0;
};

class RasterBackend {
public:
    virtual ~RasterBackend() = default;
    // Draws result.workspace.front_end.setup_chunks (the opaque setups) into result.image, sized and every pixel
    // written, and, when draw.keep_visibility, every sample into result.visibility. May use the rest of
    // result.workspace as scratch.
    virtual OpaqueDrawStats draw_opaque(const OpaqueDraw& draw, RenderResult& result) const = 0;
    // Depth only: the view depth of the nearest of workspace.front_end.setup_chunks' setups at each sample of
    // `frame`, +inf where none covers it, into view_depth in visibility-buffer order (frame.width x frame.height x
    // frame.samples() floats). May use the rest of `workspace` as scratch.
    virtual void draw_depth(const FrameParams& frame, RenderWorkspace& workspace, float* view_depth) const = 0;
};

// The backend a RasterPath names (tiled: coverage in SIMD unless allow_simd is false, the scalar fallback, same
// bytes). The objects live as long as the program.
const RasterBackend& raster_backend(RasterPath path, bool allow_simd = true);

}  // namespace raster
