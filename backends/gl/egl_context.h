// An OpenGL 4.5 core context on Mesa's EGL without any window or display (EGL_PLATFORM_SURFACELESS_MESA), current on
// the thread that made it: what the GL backend draws into framebuffer objects with. Several may live at once.
#pragma once

#include <string>

namespace raster::gl {

class EglContext {
public:
    // Makes the context current on this thread. Throws std::runtime_error saying what failed (no EGL, no surfaceless
    // platform, no OpenGL 4.5 core context).
    EglContext();
    ~EglContext();
    EglContext(const EglContext&) = delete;
    EglContext& operator=(const EglContext&) = delete;

    // GL_RENDERER and GL_VERSION, e.g. "llvmpipe (LLVM 15.0.6, 256 bits), 4.5 (Core Profile) Mesa 22.3.6".
    const std::string& description() const { return description_; }
    // Makes the context current on this thread again (another context may have been made current since).
    void make_current() const;
    int max_samples() const { return max_samples_; }  // GL_MAX_SAMPLES

private:
    void* display_ = nullptr;
    void* context_ = nullptr;
    std::string description_;
    int max_samples_ = 0;
};

}  // namespace raster::gl
