// The GL objects the backend's passes share (gl_objects.h).
#include "backends/gl/gl_objects.h"

#define GL_GLEXT_PROTOTYPES
#include <GL/glcorearb.h>

#include <stdexcept>
#include <string>

namespace raster::gl {
namespace {

GLuint compiled(GLenum kind, const char* source) {
    const GLuint shader = glCreateShader(kind);
    glShaderSource(shader, 1, &source, nullptr);
    glCompileShader(shader);
    GLint ok = 0;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[2048];
        glGetShaderInfoLog(shader, sizeof log, nullptr, log);
        glDeleteShader(shader);
        throw std::runtime_error(std::string("the GL backend's shader does not compile: ") + log);
    }
    return shader;
}

GLuint linked(const std::vector<GLuint>& shaders) {
    const GLuint program = glCreateProgram();
    for (const GLuint shader : shaders) glAttachShader(program, shader);
    glLinkProgram(program);
    for (const GLuint shader : shaders) glDeleteShader(shader);
    GLint ok = 0;
    glGetProgramiv(program, GL_LINK_STATUS, &ok);
    if (!ok) {
        char log[2048];
        glGetProgramInfoLog(program, sizeof log, nullptr, log);
        glDeleteProgram(program);
        throw std::runtime_error(std::string("the GL backend's program does not link: ") + log);
    }
    return program;
}

}  // namespace

GlProgram::GlProgram(const char* vertex, const char* fragment, const char* geometry)
    : id_(linked(geometry ? std::vector<GLuint>{compiled(GL_VERTEX_SHADER, vertex), compiled(GL_GEOMETRY_SHADER, geometry),
                                                compiled(GL_FRAGMENT_SHADER, fragment)}
                          : std::vector<GLuint>{compiled(GL_VERTEX_SHADER, vertex), compiled(GL_FRAGMENT_SHADER, fragment)})) {}

GlProgram::GlProgram(const char* compute) : id_(linked({compiled(GL_COMPUTE_SHADER, compute)})) {}

GlProgram::~GlProgram() { glDeleteProgram(id_); }

int GlProgram::uniform(const char* name) const { return glGetUniformLocation(id_, name); }

GlFramebuffer::GlFramebuffer(int width, int height, int samples, const std::vector<uint32_t>& colour_formats,
                             bool depth) {
    const GLenum target = samples > 1 ? GL_TEXTURE_2D_MULTISAMPLE : GL_TEXTURE_2D;
    const auto texture = [&](GLenum format) {
        GLuint id = 0;
        glCreateTextures(target, 1, &id);
        if (samples > 1) {
            glTextureStorage2DMultisample(id, samples, format, width, height, GL_TRUE);
        } else {
            glTextureStorage2D(id, 1, format, width, height);
            // An integer texture with the default linear filters is incomplete, and texelFetch then reads 0.
            glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
            glTextureParameteri(id, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        }
        return id;
    };
    glCreateFramebuffers(1, &framebuffer_);
    std::vector<GLenum> buffers;
    for (size_t i = 0; i < colour_formats.size(); ++i) {
        colours_.push_back(texture(colour_formats[i]));
        glNamedFramebufferTexture(framebuffer_, GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(i), colours_.back(), 0);
        buffers.push_back(GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(i));
    }
    glNamedFramebufferDrawBuffers(framebuffer_, static_cast<GLsizei>(buffers.size()), buffers.data());
    if (depth) {
        depth_ = texture(GL_DEPTH_COMPONENT32F);
        glNamedFramebufferTexture(framebuffer_, GL_DEPTH_ATTACHMENT, depth_, 0);
    }
    if (glCheckNamedFramebufferStatus(framebuffer_, GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw std::runtime_error("the GL backend's framebuffer is incomplete at " + std::to_string(samples) + " samples");
}

GlFramebuffer::~GlFramebuffer() {
    glDeleteFramebuffers(1, &framebuffer_);
    glDeleteTextures(static_cast<GLsizei>(colours_.size()), colours_.data());
    if (depth_) glDeleteTextures(1, &depth_);
}

void begin_reversed_z_pass(const GlFramebuffer& framebuffer, int width, int height, bool per_sample,
                           bool cull_backfaces) {
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.id());
    glViewport(0, 0, width, height);
    glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_GREATER);  // reversed Z: larger is nearer; a tie keeps the triangle drawn first
    if (per_sample) {  // every sample shaded at its own position
        glEnable(GL_SAMPLE_SHADING);
        glMinSampleShading(1.0f);
    } else {
        glDisable(GL_SAMPLE_SHADING);
    }
    if (cull_backfaces) {
        glEnable(GL_CULL_FACE);
        glFrontFace(GL_CW);  // counter-clockwise in NDC, seen upside down
        glCullFace(GL_BACK);
    } else {
        glDisable(GL_CULL_FACE);
    }
    const float far_depth = 0.0f;
    glClearNamedFramebufferfv(framebuffer.id(), GL_DEPTH, 0, &far_depth);
}

}  // namespace raster::gl
