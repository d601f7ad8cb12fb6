// OpenGL behind the plugin interface (gl_plugin.h).
#include "backends/gl/gl_plugin.h"

#define GL_GLEXT_PROTOTYPES
#include <GL/glcorearb.h>

#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "backends/gl/egl_context.h"
#include "backends/gl/gl_objects.h"
#include "backends/gl/gl_shaders.h"
#include "backends/gl/gl_visibility.h"

namespace raster::gl {
namespace {

// What the plugin keeps for the process: its context, the pass's program and what the implementation reports.
struct GlPluginState {
    EglContext context;
    GlProgram program{clip_space_vertex_shader_source(), visibility_fragment_shader_source(),
                      visibility_geometry_shader_source()};
    std::string name = "gl (" + context.description() + ")";
    int subpixel_bits = 0;
    std::vector<std::vector<glm::vec2>> positions;  // per sample count (index), empty where it has none

    GlPluginState() {
        glGetIntegerv(GL_SUBPIXEL_BITS, &subpixel_bits);
        positions.resize(static_cast<size_t>(context.max_samples()) + 1);
        positions[1] = {glm::vec2(0.5f)};  // a one-sample framebuffer samples at the pixel's centre
        for (int samples = 2; samples <= context.max_samples(); ++samples) {
            const GlFramebuffer probe(1, 1, samples, {GL_R32UI}, true);
            GLint actual = 0;
            glBindFramebuffer(GL_FRAMEBUFFER, probe.id());
            glGetIntegerv(GL_SAMPLES, &actual);
            if (actual != samples) continue;  // the implementation rounds this count up
            // Measured from the pixel's lower-left corner with rows bottom up; the backend draws upside down, so
            // the same numbers are raster's offsets from the upper-left corner (docs/gl.md, finding 1).
            for (int s = 0; s < samples; ++s) {
                float at[2] = {0.0f, 0.0f};
                glGetMultisamplefv(GL_SAMPLE_POSITION, static_cast<GLuint>(s), at);
                positions[static_cast<size_t>(samples)].emplace_back(at[0], at[1]);
            }
        }
    }
};

GlPluginState& state() {
    static GlPluginState plugin;
    return plugin;
}

uint32_t abi_version() { return RASTER_PLUGIN_ABI_VERSION; }
const char* name() { return state().name.c_str(); }

int refuse(raster_plugin_samples* out, const std::string& why) {
    std::snprintf(out->message, RASTER_PLUGIN_MESSAGE_SIZE, "%s", why.c_str());
    return RASTER_PLUGIN_REFUSED;
}

int draw(const raster_plugin_frame* in, raster_plugin_samples* out) {
    GlPluginState& plugin = state();
    plugin.context.make_current();
    if (in->subpixel_bits != plugin.subpixel_bits)
        return refuse(out, std::to_string(in->subpixel_bits) + " sub-pixel bits: it has " +
                               std::to_string(plugin.subpixel_bits));
    const size_t samples = static_cast<size_t>(in->samples);
    if (samples >= plugin.positions.size() || plugin.positions[samples].empty())
        return refuse(out, std::to_string(samples) + " samples per pixel: it has none such");
    if (std::memcmp(plugin.positions[samples].data(), in->sample_offsets, samples * sizeof(glm::vec2)) != 0)
        return refuse(out, "sample positions other than its own at " + std::to_string(samples) + " samples");
    const uint64_t count = uint64_t(in->width) * uint64_t(in->height) * samples;
    if (count * 16 > uint64_t(INT32_MAX)) return refuse(out, "a frame too large to read back in one call");

    GLuint array = 0, buffer = 0;
    glCreateVertexArrays(1, &array);
    glCreateBuffers(1, &buffer);
    const size_t corners = size_t{in->triangle_count} * 3;
    glNamedBufferStorage(buffer, static_cast<GLsizeiptr>(std::max<size_t>(corners, 1) * 4 * sizeof(float)),
                         corners ? in->clip_positions : nullptr, 0);
    glVertexArrayVertexBuffer(array, 0, buffer, 0, 4 * sizeof(float));
    glEnableVertexArrayAttrib(array, 0);
    glVertexArrayAttribFormat(array, 0, 4, GL_FLOAT, GL_FALSE, 0);
    glVertexArrayAttribBinding(array, 0, 0);
    VisibilityPass pass;
    pass.width = in->width;
    pass.height = in->height;
    pass.samples = in->samples;
    pass.cull_backfaces = in->cull_backfaces != 0;
    pass.program = plugin.program.id();
    pass.vertex_array = array;
    if (corners) pass.draws.push_back({0, static_cast<int>(corners), 0});
    glUseProgram(plugin.program.id());
    VisibilityBuffer visibility;
    draw_visibility_pass(pass, visibility);
    glDeleteBuffers(1, &buffer);
    glDeleteVertexArrays(1, &array);
    if (const GLenum error = glGetError(); error != GL_NO_ERROR) {
        std::snprintf(out->message, RASTER_PLUGIN_MESSAGE_SIZE, "OpenGL error 0x%04x", error);
        return RASTER_PLUGIN_FAILED;
    }
    std::memcpy(out->triangle, visibility.triangle.data(), visibility.size() * sizeof(uint32_t));
    std::memcpy(out->barycentrics, visibility.bary.data(), visibility.size() * sizeof(glm::vec3));
    out->barycentrics_written = 1;
    return RASTER_PLUGIN_DRAWN;
}

}  // namespace

std::shared_ptr<const plugin::PluginLibrary> gl_plugin() {
    state();  // the context first: its failure is std::runtime_error, not a plugin's
    return std::make_shared<plugin::PluginLibrary>(plugin::PluginFunctions{abi_version, name, draw}, "gl (in process)");
}

}  // namespace raster::gl
