// An OpenGL 4.5 core context on EGL surfaceless (egl_context.h).
#include "backends/gl/egl_context.h"

#define GL_GLEXT_PROTOTYPES
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/glcorearb.h>

#include <cstdio>
#include <stdexcept>

namespace raster::gl {
namespace {

std::string egl_error(const char* what) {
    char text[96];
    std::snprintf(text, sizeof text, "%s failed (EGL error 0x%04x)", what, static_cast<unsigned>(eglGetError()));
    return text;
}

}  // namespace

EglContext::EglContext() {
    const auto get_platform_display =
        reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (!get_platform_display) throw std::runtime_error("the GL backend: EGL has no eglGetPlatformDisplayEXT");
    EGLDisplay display = get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    EGLint major = 0, minor = 0;
    if (display == EGL_NO_DISPLAY || !eglInitialize(display, &major, &minor))
        throw std::runtime_error("the GL backend: " + egl_error("eglInitialize on Mesa's surfaceless platform") +
                                 "; install libegl-mesa0 and libgl1-mesa-dri");
    display_ = display;
    if (!eglBindAPI(EGL_OPENGL_API)) {
        eglTerminate(display);
        throw std::runtime_error("the GL backend: " + egl_error("eglBindAPI(EGL_OPENGL_API)"));
    }
    const EGLint config_attributes[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
    EGLConfig config = nullptr;
    EGLint configs = 0;
    eglChooseConfig(display, config_attributes, &config, 1, &configs);
    const EGLint context_attributes[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
                                         EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
    EGLContext context =
        eglCreateContext(display, configs > 0 ? config : EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, context_attributes);
    if (context == EGL_NO_CONTEXT || !eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) {
        const std::string message = egl_error("an OpenGL 4.5 core context");
        if (context != EGL_NO_CONTEXT) eglDestroyContext(display, context);
        eglTerminate(display);
        throw std::runtime_error("the GL backend: " + message);
    }
    context_ = context;
    description_ = std::string(reinterpret_cast<const char*>(glGetString(GL_RENDERER))) + ", " +
                   reinterpret_cast<const char*>(glGetString(GL_VERSION));
    glGetIntegerv(GL_MAX_SAMPLES, &max_samples_);
}

void EglContext::make_current() const {
    if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_))
        throw std::runtime_error("the GL backend: " + egl_error("eglMakeCurrent"));
}

// The display stays initialised: the surfaceless display is one per process, and terminating it would destroy
// every other context on it (the GL plugin keeps one for the process, while GL renderers come and go).
EglContext::~EglContext() {
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(display_, context_);
}

}  // namespace raster::gl
