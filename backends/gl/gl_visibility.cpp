// The visibility pass and its read back (gl_visibility.h).
#include "backends/gl/gl_visibility.h"

#define GL_GLEXT_PROTOTYPES
#include <GL/glcorearb.h>

#include <algorithm>

#include <glm/gtc/type_ptr.hpp>

#include "backends/gl/gl_objects.h"
#include "backends/gl/gl_shaders.h"

namespace raster::gl {

void draw_visibility_pass(const VisibilityPass& pass, VisibilityBuffer& out) {
    const int width = pass.width, height = pass.height, samples = pass.samples;
    const GlFramebuffer frame(width, height, samples, {GL_R32UI, GL_RGBA32F}, true);
    begin_reversed_z_pass(frame, width, height, true, pass.cull_backfaces);
    const GLuint empty = kNoTriangle;
    glClearNamedFramebufferuiv(frame.id(), GL_COLOR, 0, &empty);
    const glm::vec4 zero(0.0f);
    glClearNamedFramebufferfv(frame.id(), GL_COLOR, 1, glm::value_ptr(zero));
    glUseProgram(pass.program);
    glUniform2f(glGetUniformLocation(pass.program, "viewport"), static_cast<float>(width), static_cast<float>(height));
    const GLint first_triangle = glGetUniformLocation(pass.program, "first_triangle");
    glBindVertexArray(pass.vertex_array);
    for (const VisibilityDraw& draw : pass.draws) {
        glUniform1ui(first_triangle, draw.first_triangle);
        glDrawArrays(GL_TRIANGLES, draw.first_corner, draw.corners);
    }

    const size_t count = static_cast<size_t>(width) * static_cast<size_t>(height) * static_cast<size_t>(samples);
    GLuint buffers[2] = {0, 0};
    glCreateBuffers(2, buffers);
    glNamedBufferStorage(buffers[0], static_cast<GLsizeiptr>(count * sizeof(uint32_t)), nullptr, 0);
    glNamedBufferStorage(buffers[1], static_cast<GLsizeiptr>(count * sizeof(glm::vec4)), nullptr, 0);
    const GlProgram readback(visibility_readback_source(samples > 1).c_str());
    glUseProgram(readback.id());
    glUniform1i(readback.uniform("width"), width);
    glUniform1i(readback.uniform("samples"), samples);
    glUniform1i(readback.uniform("count"), static_cast<GLint>(count));
    glBindTextureUnit(0, frame.colour(0));
    glBindTextureUnit(1, frame.colour(1));
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, buffers[0]);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, buffers[1]);
    const size_t groups = (count + 63) / 64, columns = std::min<size_t>(groups, 65535);
    glDispatchCompute(static_cast<GLuint>(columns), static_cast<GLuint>((groups + columns - 1) / columns), 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    std::vector<uint32_t> ids(count);
    std::vector<glm::vec4> data(count);
    glGetNamedBufferSubData(buffers[0], 0, static_cast<GLsizeiptr>(count * sizeof(uint32_t)), ids.data());
    glGetNamedBufferSubData(buffers[1], 0, static_cast<GLsizeiptr>(count * sizeof(glm::vec4)), data.data());
    glDeleteBuffers(2, buffers);

    out.resize(width, height, samples);
    for (size_t i = 0; i < count; ++i) {
        out.triangle[i] = ids[i];
        const bool covered = ids[i] != kNoTriangle;
        out.bary[i] = covered ? glm::vec3(data[i]) : glm::vec3(0.0f);
        out.view_depth[i] = covered ? data[i].w : 0.0f;
    }
}

}  // namespace raster::gl
