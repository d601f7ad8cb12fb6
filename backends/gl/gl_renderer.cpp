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
#include "backends/gl/gl_objects.h"
#include "backends/gl/gl_scene.h"
#include "backends/gl/gl_shaders.h"
#include "backends/gl/gl_visibility.h"
#include "raster/core/errors.h"
#include "raster/core/stopwatch.h"

namespace raster::gl {
namespace {

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

// The scene's corners in one vertex buffer, position, normal and colour at locations 0, 1 and 2.
class VertexInput {
public:
    explicit VertexInput(const std::vector<GlCorner>& corners) {
        glCreateVertexArrays(1, &array_);
        glCreateBuffers(1, &buffer_);
        // At least one corner's bytes: GL refuses an empty store, and a scene may have no triangle.
        glNamedBufferStorage(buffer_, static_cast<GLsizeiptr>(std::max<size_t>(corners.size(), 1) * sizeof(GlCorner)),
                             corners.empty() ? nullptr : corners.data(), 0);
        glVertexArrayVertexBuffer(array_, 0, buffer_, 0, sizeof(GlCorner));
        for (GLuint attribute = 0; attribute < 3; ++attribute) {
            glEnableVertexArrayAttrib(array_, attribute);
            glVertexArrayAttribFormat(array_, attribute, 3, GL_FLOAT, GL_FALSE,
                                      static_cast<GLuint>(attribute * sizeof(glm::vec3)));
            glVertexArrayAttribBinding(array_, attribute, 0);
        }
    }
    ~VertexInput() {
        glDeleteBuffers(1, &buffer_);
        glDeleteVertexArrays(1, &array_);
    }
    VertexInput(const VertexInput&) = delete;
    VertexInput& operator=(const VertexInput&) = delete;
    GLuint array() const { return array_; }

private:
    GLuint array_ = 0, buffer_ = 0;
};

// The visibility pass over the scene's draws (gl_visibility.h), its view depth the distance along the view direction.
void draw_visibility(const Scene& scene, const GlScene& drawn, const VertexInput& input, const glm::mat4& clip,
                     VisibilityBuffer& visibility) {
    const GlProgram program(visibility_vertex_shader_source(), visibility_fragment_shader_source(),
                            visibility_geometry_shader_source());
    glUseProgram(program.id());
    glUniformMatrix4fv(program.uniform("view_projection"), 1, GL_FALSE, glm::value_ptr(clip));
    glUniform3fv(program.uniform("eye"), 1, glm::value_ptr(scene.camera.eye));
    const glm::vec3 forward = glm::normalize(scene.camera.target - scene.camera.eye);
    glUniform3fv(program.uniform("forward"), 1, glm::value_ptr(forward));
    VisibilityPass pass;
    pass.width = scene.settings.width;
    pass.height = scene.settings.height;
    pass.samples = scene.settings.samples;
    pass.cull_backfaces = scene.settings.cull_backfaces;
    pass.program = program.id();
    pass.vertex_array = input.array();
    for (const GlDraw& draw : drawn.draws)
        pass.draws.push_back({static_cast<int>(draw.first_corner), static_cast<int>(draw.corners),
                              static_cast<uint32_t>(draw.first_corner / 3)});
    draw_visibility_pass(pass, visibility);
}

}  // namespace

void GlRenderer::render_into(const Scene& scene, const RenderOptions& options, RenderResult& result) const {
    const RenderSettings& settings = scene.settings;
    if (const std::string problem = unsupported_by_gl(scene); !problem.empty())
        throw InputError("the GL backend does not draw " + problem);
    if (options.alpha) throw InputError("the GL backend does not write alpha");
    const Clock::time_point start = Clock::now();
    const EglContext context;
    name_ = "gl (" + context.description() + ")";
    if (settings.samples > context.max_samples())
        throw InputError("the GL backend draws " + std::to_string(settings.samples) + " samples per pixel, but " +
                         context.description() + " has " + std::to_string(context.max_samples()) + " at most");
    const int width = settings.width, height = settings.height, samples = settings.samples;
    const GlScene drawn = gl_scene(scene);
    const VertexInput input(drawn.corners);
    const glm::mat4 clip = view_projection(scene.camera, width, height);

    const GlFramebuffer frame(width, height, samples, {GL_RGBA32F}, true);
    // Supersampling shades every sample.
    begin_reversed_z_pass(frame, width, height, samples > 1, settings.cull_backfaces);
    const glm::vec4 background(settings.background, 1.0f);
    glClearNamedFramebufferfv(frame.id(), GL_COLOR, 0, glm::value_ptr(background));
    const GlProgram program(vertex_shader_source(), fragment_shader_source());
    glUseProgram(program.id());
    glUniformMatrix4fv(program.uniform("view_projection"), 1, GL_FALSE, glm::value_ptr(clip));
    set_lighting_uniforms(program.id(), scene);
    glBindVertexArray(input.array());
    for (const GlDraw& draw : drawn.draws) {
        const Material& m = *draw.material;
        glUniform3fv(program.uniform("ambient"), 1, glm::value_ptr(m.ambient));
        glUniform3fv(program.uniform("diffuse"), 1, glm::value_ptr(m.diffuse));
        glUniform3fv(program.uniform("specular"), 1, glm::value_ptr(m.specular));
        glUniform1f(program.uniform("exponent"), m.exponent);
        glDrawArrays(GL_TRIANGLES, static_cast<GLint>(draw.first_corner), static_cast<GLsizei>(draw.corners));
    }

    // The resolve: the samples averaged by a blit into a one-sample float framebuffer, read back from row 0, the top.
    const GlFramebuffer resolved(width, height, 1, {GL_RGBA32F}, false);
    glBlitNamedFramebuffer(frame.id(), resolved.id(), 0, 0, width, height, 0, 0, width, height, GL_COLOR_BUFFER_BIT,
                           GL_NEAREST);
    std::vector<float> pixels(static_cast<size_t>(width) * static_cast<size_t>(height) * 4);
    glGetTextureImage(resolved.colour(0), 0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(pixels.size() * sizeof(float)),
                      pixels.data());
    if (options.keep_visibility) draw_visibility(scene, drawn, input, clip, result.visibility);
    if (const GLenum error = glGetError(); error != GL_NO_ERROR)
        throw std::runtime_error("the GL backend: OpenGL error " + std::to_string(error));

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
