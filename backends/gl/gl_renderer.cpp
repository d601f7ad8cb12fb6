// The GL backend's frame (gl_renderer.h): the program, the vertex buffer, a float framebuffer at the frame's
// sample count with reversed-Z depth, one draw per material, the resolve by blit and the read back.
#include "backends/gl/gl_renderer.h"

#define GL_GLEXT_PROTOTYPES
#include <GL/glcorearb.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <vector>

#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "backends/gl/egl_context.h"
#include "backends/gl/gl_scene.h"
#include "backends/gl/gl_shaders.h"
#include "raster/core/errors.h"
#include "raster/core/stopwatch.h"

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
        throw std::runtime_error(std::string("the GL backend's shader does not compile: ") + log);
    }
    return shader;
}

GLuint linked_program() {
    const GLuint program = glCreateProgram();
    const GLuint vertex = compiled(GL_VERTEX_SHADER, vertex_shader_source());
    const GLuint fragment = compiled(GL_FRAGMENT_SHADER, fragment_shader_source());
    glAttachShader(program, vertex);
    glAttachShader(program, fragment);
    glLinkProgram(program);
    GLint ok = 0;
    glGetProgramiv(program, GL_LINK_STATUS, &ok);
    if (!ok) {
        char log[2048];
        glGetProgramInfoLog(program, sizeof log, nullptr, log);
        throw std::runtime_error(std::string("the GL backend's program does not link: ") + log);
    }
    glDeleteShader(vertex);
    glDeleteShader(fragment);
    return program;
}

// The view and a reversed-Z projection (depth 1 at near, 0 at far; with glClipControl's 0..1 depth range), upside down.
glm::mat4 view_projection(const Camera& camera, int width, int height) {
    const float aspect = static_cast<float>(width) / static_cast<float>(height);
    const glm::mat4 view = glm::lookAtRH(camera.eye, camera.target, camera.up);
    glm::mat4 projection;
    if (camera.projection == Projection::orthographic) {
        const float half_height = camera.ortho_height / 2.0f, half_width = half_height * aspect;
        projection = glm::orthoRH_ZO(-half_width, half_width, -half_height, half_height, camera.far, camera.near);
    } else {
        projection = glm::perspectiveRH_ZO(glm::radians(camera.fov_y_degrees), aspect, camera.far, camera.near);
    }
    // GL's window rows run bottom up and its sample positions are measured from a pixel's lower-left corner. Drawn
    // upside down (y negated in clip space), row 0 is the image's top and every position is measured from the
    // pixel's upper-left corner, as raster's conventions measure them: the same standard pattern, not its mirror.
    const glm::mat4 flip = glm::scale(glm::mat4(1.0f), glm::vec3(1.0f, -1.0f, 1.0f));
    return flip * projection * view;
}

void set_lighting_uniforms(GLuint program, const Scene& scene) {
    const Camera& camera = scene.camera;
    const auto at = [program](const char* name) { return glGetUniformLocation(program, name); };
    glUniform1i(at("mode"), scene.settings.shading == ShadingMode::unlit ? 0
                            : scene.settings.shading == ShadingMode::phong ? 1
                                                                            : 2);
    glUniform3fv(at("ambient_light"), 1, glm::value_ptr(scene.settings.ambient_light));
    glUniform3fv(at("eye"), 1, glm::value_ptr(camera.eye));
    glUniform1i(at("orthographic"), camera.projection == Projection::orthographic);
    const glm::vec3 back = glm::normalize(camera.eye - camera.target);
    glUniform3fv(at("back_direction"), 1, glm::value_ptr(back));
    glUniform1i(at("light_count"), static_cast<GLint>(scene.lights.size()));
    // An element of a light array: "light_type[2]".
    const auto element = [program](const char* array, size_t i) {
        char name[64];
        std::snprintf(name, sizeof name, "%s[%zu]", array, i);
        return glGetUniformLocation(program, name);
    };
    for (size_t i = 0; i < scene.lights.size(); ++i) {
        const Light& light = scene.lights[i];
        const glm::vec3 radiance = light.intensity * light.color;
        const glm::vec3 direction = glm::normalize(light.direction);
        const SpotFade fade = spot_fade(light);
        glUniform1i(element("light_type", i), light.type == LightType::point ? 0
                                                        : light.type == LightType::directional ? 1
                                                                                                 : 2);
        glUniform3fv(element("light_position", i), 1, glm::value_ptr(light.position));
        glUniform3fv(element("light_direction", i), 1, glm::value_ptr(direction));
        glUniform3fv(element("light_radiance", i), 1, glm::value_ptr(radiance));
        glUniform1i(element("light_attenuate", i), light.attenuate);
        glUniform2f(element("light_spot", i), fade.scale, fade.offset);
    }
}

// A framebuffer with a float colour attachment and a float depth attachment at `samples` (1: not multisampled).
struct Framebuffer {
    GLuint framebuffer = 0, colour = 0, depth = 0;
    Framebuffer(int width, int height, int samples, bool with_depth) {
        const GLenum target = samples > 1 ? GL_TEXTURE_2D_MULTISAMPLE : GL_TEXTURE_2D;
        glCreateFramebuffers(1, &framebuffer);
        glCreateTextures(target, 1, &colour);
        if (samples > 1) glTextureStorage2DMultisample(colour, samples, GL_RGBA32F, width, height, GL_TRUE);
        else glTextureStorage2D(colour, 1, GL_RGBA32F, width, height);
        glNamedFramebufferTexture(framebuffer, GL_COLOR_ATTACHMENT0, colour, 0);
        if (with_depth) {
            glCreateTextures(target, 1, &depth);
            if (samples > 1) glTextureStorage2DMultisample(depth, samples, GL_DEPTH_COMPONENT32F, width, height, GL_TRUE);
            else glTextureStorage2D(depth, 1, GL_DEPTH_COMPONENT32F, width, height);
            glNamedFramebufferTexture(framebuffer, GL_DEPTH_ATTACHMENT, depth, 0);
        }
        if (glCheckNamedFramebufferStatus(framebuffer, GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
            throw std::runtime_error("the GL backend's framebuffer is incomplete at " + std::to_string(samples) +
                                     " samples");
    }
    ~Framebuffer() {
        glDeleteFramebuffers(1, &framebuffer);
        glDeleteTextures(1, &colour);
        if (depth) glDeleteTextures(1, &depth);
    }
};

}  // namespace

void GlRenderer::render_into(const Scene& scene, const RenderOptions& options, RenderResult& result) const {
    const RenderSettings& settings = scene.settings;
    if (const std::string problem = unsupported_by_gl(scene); !problem.empty())
        throw InputError("the GL backend does not draw " + problem);
    if (options.alpha) throw InputError("the GL backend does not write alpha");
    const Clock::time_point start = Clock::now();
    const EglContext context;
    name_ = "gl (" + context.description() + ")";
    if (settings.samples != 1 && settings.samples != 4)
        throw InputError("the GL backend draws 1 or 4 samples per pixel (" + context.description() + " has " +
                         std::to_string(context.max_samples()) + " at most), not " + std::to_string(settings.samples));
    const int width = settings.width, height = settings.height, samples = settings.samples;
    const GlScene drawn = gl_scene(scene);

    const GLuint program = linked_program();
    GLuint vertex_array = 0, buffer = 0;
    glCreateVertexArrays(1, &vertex_array);
    glCreateBuffers(1, &buffer);
    glNamedBufferStorage(buffer, static_cast<GLsizeiptr>(drawn.corners.size() * sizeof(GlCorner)),
                         drawn.corners.empty() ? nullptr : drawn.corners.data(), 0);
    glVertexArrayVertexBuffer(vertex_array, 0, buffer, 0, sizeof(GlCorner));
    for (GLuint attribute = 0; attribute < 3; ++attribute) {
        glEnableVertexArrayAttrib(vertex_array, attribute);
        glVertexArrayAttribFormat(vertex_array, attribute, 3, GL_FLOAT, GL_FALSE,
                                  static_cast<GLuint>(attribute * sizeof(glm::vec3)));
        glVertexArrayAttribBinding(vertex_array, attribute, 0);
    }

    const Framebuffer frame(width, height, samples, true);
    glBindFramebuffer(GL_FRAMEBUFFER, frame.framebuffer);
    glViewport(0, 0, width, height);
    glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_GREATER);  // reversed Z: larger is nearer; a tie keeps the triangle drawn first
    if (samples > 1 && !settings.msaa) {  // supersampling: every sample shaded at its own position
        glEnable(GL_SAMPLE_SHADING);
        glMinSampleShading(1.0f);
    }
    if (settings.cull_backfaces) {
        glEnable(GL_CULL_FACE);
        glFrontFace(GL_CW);  // counter-clockwise in NDC, seen upside down
        glCullFace(GL_BACK);
    }
    const glm::vec4 background(settings.background, 1.0f);
    glClearNamedFramebufferfv(frame.framebuffer, GL_COLOR, 0, glm::value_ptr(background));
    const float far_depth = 0.0f;
    glClearNamedFramebufferfv(frame.framebuffer, GL_DEPTH, 0, &far_depth);

    glUseProgram(program);
    const glm::mat4 clip = view_projection(scene.camera, width, height);
    glUniformMatrix4fv(glGetUniformLocation(program, "view_projection"), 1, GL_FALSE, glm::value_ptr(clip));
    set_lighting_uniforms(program, scene);
    glBindVertexArray(vertex_array);
    for (const GlDraw& draw : drawn.draws) {
        const Material& m = *draw.material;
        glUniform3fv(glGetUniformLocation(program, "ambient"), 1, glm::value_ptr(m.ambient));
        glUniform3fv(glGetUniformLocation(program, "diffuse"), 1, glm::value_ptr(m.diffuse));
        glUniform3fv(glGetUniformLocation(program, "specular"), 1, glm::value_ptr(m.specular));
        glUniform1f(glGetUniformLocation(program, "exponent"), m.exponent);
        glDrawArrays(GL_TRIANGLES, static_cast<GLint>(draw.first_corner), static_cast<GLsizei>(draw.corners));
    }

    // The resolve: the samples averaged by a blit into a one-sample float framebuffer, read back from row 0, the top.
    const Framebuffer resolved(width, height, 1, false);
    glBlitNamedFramebuffer(frame.framebuffer, resolved.framebuffer, 0, 0, width, height, 0, 0, width, height,
                           GL_COLOR_BUFFER_BIT, GL_NEAREST);
    std::vector<float> pixels(static_cast<size_t>(width) * static_cast<size_t>(height) * 4);
    glGetTextureImage(resolved.colour, 0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(pixels.size() * sizeof(float)),
                      pixels.data());
    if (const GLenum error = glGetError(); error != GL_NO_ERROR)
        throw std::runtime_error("the GL backend: OpenGL error 0x" + std::to_string(error));
    glDeleteBuffers(1, &buffer);
    glDeleteVertexArrays(1, &vertex_array);
    glDeleteProgram(program);

    result.image = Image(width, height, 3);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const float* texel = &pixels[(static_cast<size_t>(y) * static_cast<size_t>(width) + x) * 4];
            for (int c = 0; c < 3; ++c)  // docs/conventions.md "Bytes"
                result.image.at(x, y)[c] =
                    static_cast<uint8_t>(std::floor(std::clamp(texel[c], 0.0f, 1.0f) * 255.0f + 0.5f));
        }
    result.stats = RenderStats{};
    result.stats.triangles = drawn.corners.size() / 3;
    result.stats.samples = static_cast<size_t>(width) * static_cast<size_t>(height) * static_cast<size_t>(samples);
    result.stats.ms_total = milliseconds_since(start);
}

}  // namespace raster::gl
