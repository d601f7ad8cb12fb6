// The llvmpipe peer: Mesa's llvmpipe through OSMesa drawing a raster scene with the same camera, triangles,
// normals and per-fragment Blinn-Phong as raster, so raster_bench can time both in one run.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "raster/scene/scene.h"

namespace raster_bench {

class LlvmpipePeer {
public:
    // Sets LP_NUM_THREADS=threads (llvmpipe's rasterizer threads; read when the first context is created), creates
    // an OSMesa compatibility context with a 24-bit depth buffer, compiles the shading program and uploads the
    // scene's vertex-stage world positions, normals and indices once. Only what the bench scenes use is supported:
    // blinn-phong shading and material colours (no vertex or face colours). Throws std::runtime_error.
    // Several peers may coexist: each makes its own context current before drawing.
    LlvmpipePeer(const raster::Scene& scene, int threads);
    ~LlvmpipePeer();
    LlvmpipePeer(const LlvmpipePeer&) = delete;
    LlvmpipePeer& operator=(const LlvmpipePeer&) = delete;

    // 1: draw straight into the OSMesa buffer. 4: draw into a 4-sample FBO, resolved into the OSMesa buffer by
    // glBlitFramebuffer. Throws std::runtime_error for anything llvmpipe cannot do.
    void set_samples(int samples);
    int samples() const;

    // One frame: clear colour and depth, draw every mesh, resolve when multisampled, glFinish.
    void draw_frame();

    // The OSMesa colour buffer as of the last draw_frame, RGBA8, flipped so row 0 is the top (raster's order).
    std::vector<uint8_t> image_top_down() const;

    size_t triangles() const;
    std::string renderer() const;  // GL_RENDERER and GL_VERSION

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace raster_bench
