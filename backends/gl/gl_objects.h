// The GL objects the backend's passes share: programs linked from GLSL source (each failure thrown with the
// compiler's log), and framebuffers of float or integer colour attachments and a depth attachment at a sample count.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace raster::gl {

// A program of a vertex, an optional geometry and a fragment shader, or of a compute shader.
// Throws std::runtime_error with the compiler's or linker's log. Deleted by the destructor.
class GlProgram {
public:
    GlProgram(const char* vertex, const char* fragment, const char* geometry = nullptr);
    explicit GlProgram(const char* compute);
    ~GlProgram();
    GlProgram(const GlProgram&) = delete;
    GlProgram& operator=(const GlProgram&) = delete;
    uint32_t id() const { return id_; }
    int uniform(const char* name) const;

private:
    uint32_t id_ = 0;
};

// A framebuffer with a colour attachment per format (GL_RGBA32F, GL_R32UI, ...) and, with `depth`, a 32-bit float
// depth attachment, all at `samples` (1: plain 2D textures). Throws std::runtime_error when it is incomplete.
class GlFramebuffer {
public:
    GlFramebuffer(int width, int height, int samples, const std::vector<uint32_t>& colour_formats, bool depth);
    ~GlFramebuffer();
    GlFramebuffer(const GlFramebuffer&) = delete;
    GlFramebuffer& operator=(const GlFramebuffer&) = delete;
    uint32_t id() const { return framebuffer_; }
    uint32_t colour(size_t index) const { return colours_[index]; }

private:
    uint32_t framebuffer_ = 0, depth_ = 0;
    std::vector<uint32_t> colours_;
};

// Binds `framebuffer` for a pass over width x height pixels with raster's conventions: reversed-Z float depth (0..1
// clip range, GL_GREATER, cleared to 0, the far value; a tie keeps the triangle drawn first), every sample shaded at
// its own position when `per_sample`, and back faces culled when `cull_backfaces` (counter-clockwise in NDC is front,
// seen upside down: the backend draws with y negated).
void begin_reversed_z_pass(const GlFramebuffer& framebuffer, int width, int height, bool per_sample,
                           bool cull_backfaces);

}  // namespace raster::gl
