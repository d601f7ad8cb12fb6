// The visibility pass: triangles drawn into a triangle-id attachment (R32UI) and a barycentrics-and-view-depth one
// (RGBA32F) at the frame's sample count, each sample's barycentrics solved by the fragment shader from the whole
// original triangle (docs/gl.md, finding 2), and both read back in raster's sample order. The GL renderer runs it
// over a scene's draws, the GL plugin over clip-space triangles.
#pragma once

#include <cstdint>
#include <vector>

#include "raster/frame/frame.h"  // VisibilityBuffer

namespace raster::gl {

// One draw of the pass: `corners` corners of the bound vertex array from `first_corner`, its first triangle's id.
struct VisibilityDraw {
    int first_corner = 0;
    int corners = 0;
    uint32_t first_triangle = 0;
};

struct VisibilityPass {
    int width = 0, height = 0, samples = 1;
    bool cull_backfaces = false;
    uint32_t program = 0;       // in use, its own uniforms set: a vertex shader of the caller's, and the pass's
                                // geometry and fragment shaders (gl_shaders.h)
    uint32_t vertex_array = 0;  // what the vertex shader reads
    std::vector<VisibilityDraw> draws;
};

// Draws the pass and reads it back into `out`: per sample the triangle id (kNoTriangle where none), barycentrics and
// the fragment shader's view depth; zero for empty samples.
void draw_visibility_pass(const VisibilityPass& pass, VisibilityBuffer& out);

}  // namespace raster::gl
