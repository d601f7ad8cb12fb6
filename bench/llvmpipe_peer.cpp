// The llvmpipe peer: an OSMesa context, one VBO/IBO uploaded at construction, a GLSL 1.30 per-fragment
// Blinn-Phong program matching raster::evaluate_lighting, and an optional 4-sample FBO.
#include "bench/llvmpipe_peer.h"

// libOSMesa exports the GL entry points itself, so the prototypes link directly against it.
#define GL_GLEXT_PROTOTYPES 1
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "raster/geometry/vertex_stage.h"

namespace raster_bench {
namespace {

constexpr int kMaxLights = 16;

const char* const kVertexShader = R"(#version 130
uniform mat4 u_view_projection;
in vec3 a_position;  // world space (raster's vertex stage)
in vec3 a_normal;    // world space, unit (raster's vertex stage)
out vec3 v_position;
out vec3 v_normal;
void main() {
    v_position = a_position;
    v_normal = a_normal;
    gl_Position = u_view_projection * vec4(a_position, 1.0);
}
)";

// raster::evaluate_lighting with SpecularModel::blinn, line for line; colour = base * diffuse + specular.
const char* const kFragmentShader = R"(#version 130
const int kMaxLights = 16;
uniform vec3 u_eye;
uniform int u_light_count;
uniform vec3 u_light_position[kMaxLights];
uniform vec3 u_light_radiance[kMaxLights];  // colour * intensity
uniform float u_light_attenuate[kMaxLights];  // 1: divide by r^2
uniform vec3 u_base;
uniform vec3 u_ambient;  // material ambient * scene ambient light
uniform vec3 u_diffuse;
uniform vec3 u_specular;
uniform float u_exponent;
in vec3 v_position;
in vec3 v_normal;
vec3 unit_or_zero(vec3 v) {
    float l = length(v);
    return l > 0.0 ? v / l : vec3(0.0);
}
void main() {
    vec3 n = unit_or_zero(v_normal);
    vec3 to_eye = unit_or_zero(u_eye - v_position);
    vec3 diffuse = u_ambient;
    vec3 specular = vec3(0.0);
    for (int i = 0; i < u_light_count; ++i) {
        vec3 to_light = u_light_position[i] - v_position;
        float d2 = dot(to_light, to_light);
        if (!(d2 > 0.0)) continue;
        to_light /= sqrt(d2);
        float n_dot_l = dot(n, to_light);
        if (n_dot_l <= 0.0) continue;
        vec3 radiance = u_light_radiance[i];
        if (u_light_attenuate[i] != 0.0) radiance /= d2;
        float lobe = max(0.0, dot(n, normalize(to_light + to_eye)));
        diffuse += radiance * u_diffuse * n_dot_l;
        specular += radiance * u_specular * pow(lobe, u_exponent);
    }
    gl_FragColor = vec4(u_base * diffuse + specular, 1.0);
}
)";

// The standard OpenGL perspective (depth to [-1, 1]) from the same fov / aspect / near / far as
// raster::perspective_matrix; x, y and w are the same expressions, so the screen footprint is identical.
glm::mat4 gl_perspective(const raster::Camera& camera, int width, int height) {
    const double focal = 1.0 / std::tan(static_cast<double>(camera.fov_y_degrees) * (M_PI / 360.0));
    const double aspect = static_cast<double>(static_cast<float>(width) / static_cast<float>(height));
    const double n = camera.near, f = camera.far;
    glm::mat4 m(0.0f);
    m[0][0] = float(focal / aspect);
    m[1][1] = float(focal);
    m[2][2] = float((f + n) / (n - f));
    m[3][2] = float(2.0 * f * n / (n - f));
    m[2][3] = -1.0f;
    return m;
}

void check_gl(const char* what) {
    if (const GLenum error = glGetError(); error != GL_NO_ERROR)
        throw std::runtime_error(std::string("llvmpipe peer: GL error ") + std::to_string(error) + " in " + what);
}

GLuint compile(GLenum type, const char* source) {
    const GLuint shader = glCreateShader(type);
    glShaderSource(shader, 1, &source, nullptr);
    glCompileShader(shader);
    GLint ok = GL_FALSE;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[4096] = {};
        glGetShaderInfoLog(shader, sizeof log, nullptr, log);
        throw std::runtime_error(std::string("llvmpipe peer: shader does not compile: ") + log);
    }
    return shader;
}

}  // namespace

struct LlvmpipePeer::Impl {
    struct MeshDraw {
        GLsizei index_count = 0;
        size_t index_offset_bytes = 0;
        glm::vec3 base, ambient, diffuse, specular;
        float exponent = 0.0f;
    };

    int width = 0, height = 0;
    glm::vec3 background{0.0f};
    OSMesaContext context = nullptr;
    std::vector<uint8_t> buffer;  // OSMesa's colour buffer, RGBA8, bottom row first
    GLuint program = 0, vbo = 0, ibo = 0;
    GLuint fbo = 0, color_rb = 0, depth_rb = 0;
    int samples = 1;
    size_t triangles = 0;
    std::vector<MeshDraw> draws;
    GLint loc_base = -1, loc_ambient = -1, loc_diffuse = -1, loc_specular = -1, loc_exponent = -1;

    // Several peers (one per scene) may live in one process: each GL call sequence starts by making this
    // peer's context current, which is free when it already is.
    void make_current() {
        if (OSMesaGetCurrentContext() != context &&
            !OSMesaMakeCurrent(context, buffer.data(), GL_UNSIGNED_BYTE, width, height))
            throw std::runtime_error("llvmpipe peer: OSMesaMakeCurrent failed");
    }

    void release_fbo() {
        if (fbo) glDeleteFramebuffers(1, &fbo);
        if (color_rb) glDeleteRenderbuffers(1, &color_rb);
        if (depth_rb) glDeleteRenderbuffers(1, &depth_rb);
        fbo = color_rb = depth_rb = 0;
    }
};

LlvmpipePeer::LlvmpipePeer(const raster::Scene& scene, int threads) : impl_(std::make_unique<Impl>()) {
    Impl& p = *impl_;
    const raster::RenderSettings& settings = scene.settings;
    if (settings.shading != raster::ShadingMode::blinn_phong)
        throw std::runtime_error("llvmpipe peer: only blinn-phong shading is implemented");
    if (scene.lights.size() > kMaxLights)
        throw std::runtime_error("llvmpipe peer: at most " + std::to_string(kMaxLights) + " lights");
    for (const raster::SceneMesh& mesh : scene.meshes)
        if (!mesh.data->colors.empty() || !mesh.data->face_colors.empty())
            throw std::runtime_error("llvmpipe peer: vertex and face colours are not implemented");

    p.width = settings.width;
    p.height = settings.height;
    p.background = settings.background;

    // llvmpipe reads LP_NUM_THREADS when OSMesa creates its screen, i.e. with the first context.
    setenv("LP_NUM_THREADS", std::to_string(threads).c_str(), 1);
    const int attributes[] = {OSMESA_FORMAT,      OSMESA_RGBA, OSMESA_DEPTH_BITS, 24, OSMESA_STENCIL_BITS, 0,
                              OSMESA_ACCUM_BITS,  0,           OSMESA_PROFILE,    OSMESA_COMPAT_PROFILE, 0};
    p.context = OSMesaCreateContextAttribs(attributes, nullptr);
    if (!p.context) throw std::runtime_error("llvmpipe peer: OSMesaCreateContextAttribs failed");
    p.buffer.assign(static_cast<size_t>(p.width) * p.height * 4, 0);
    if (!OSMesaMakeCurrent(p.context, p.buffer.data(), GL_UNSIGNED_BYTE, p.width, p.height))
        throw std::runtime_error("llvmpipe peer: OSMesaMakeCurrent failed");

    // Geometry exactly as raster's vertex stage produces it: world positions and unit normals per vertex.
    const raster::TransformedScene geometry = raster::run_vertex_stage(scene, raster::VertexStageNeeds{true, true});
    std::vector<float> vertices;
    vertices.reserve(geometry.world_position.size() * 6);
    for (size_t i = 0; i < geometry.world_position.size(); ++i) {
        const glm::vec3& q = geometry.world_position[i];
        const glm::vec3& n = geometry.world_normal[i];
        vertices.insert(vertices.end(), {q.x, q.y, q.z, n.x, n.y, n.z});
    }
    std::vector<uint32_t> indices;
    indices.reserve(geometry.triangles.size() * 3);
    for (const raster::TriangleIndices& t : geometry.triangles) indices.insert(indices.end(), {t.v[0], t.v[1], t.v[2]});
    p.triangles = geometry.triangles.size();

    for (size_t m = 0; m < scene.meshes.size(); ++m) {
        const raster::Material& material = scene.meshes[m].material;
        const size_t first = geometry.mesh_first_triangle[m];
        const size_t end = m + 1 < scene.meshes.size() ? geometry.mesh_first_triangle[m + 1] : geometry.triangles.size();
        Impl::MeshDraw draw;
        draw.index_count = static_cast<GLsizei>((end - first) * 3);
        draw.index_offset_bytes = first * 3 * sizeof(uint32_t);
        draw.base = material.color;
        draw.ambient = material.ambient * settings.ambient_light;
        draw.diffuse = material.diffuse;
        draw.specular = material.specular;
        draw.exponent = material.exponent;
        p.draws.push_back(draw);
    }

    glGenBuffers(1, &p.vbo);
    glBindBuffer(GL_ARRAY_BUFFER, p.vbo);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(float)), vertices.data(),
                 GL_STATIC_DRAW);
    glGenBuffers(1, &p.ibo);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, p.ibo);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(indices.size() * sizeof(uint32_t)),
                 indices.data(), GL_STATIC_DRAW);
    check_gl("buffer upload");

    const GLuint vs = compile(GL_VERTEX_SHADER, kVertexShader);
    const GLuint fs = compile(GL_FRAGMENT_SHADER, kFragmentShader);
    p.program = glCreateProgram();
    glAttachShader(p.program, vs);
    glAttachShader(p.program, fs);
    glBindAttribLocation(p.program, 0, "a_position");
    glBindAttribLocation(p.program, 1, "a_normal");
    glLinkProgram(p.program);
    GLint linked = GL_FALSE;
    glGetProgramiv(p.program, GL_LINK_STATUS, &linked);
    if (!linked) {
        char log[4096] = {};
        glGetProgramInfoLog(p.program, sizeof log, nullptr, log);
        throw std::runtime_error(std::string("llvmpipe peer: program does not link: ") + log);
    }
    glDeleteShader(vs);
    glDeleteShader(fs);
    glUseProgram(p.program);

    // Scene-wide uniforms, set once.
    const glm::mat4 view_projection =
        gl_perspective(scene.camera, p.width, p.height) * raster::view_matrix(scene.camera);
    glUniformMatrix4fv(glGetUniformLocation(p.program, "u_view_projection"), 1, GL_FALSE, &view_projection[0][0]);
    glUniform3fv(glGetUniformLocation(p.program, "u_eye"), 1, &scene.camera.eye[0]);
    glUniform1i(glGetUniformLocation(p.program, "u_light_count"), static_cast<GLint>(scene.lights.size()));
    std::vector<glm::vec3> light_position, light_radiance;
    std::vector<float> light_attenuate;
    for (const raster::Light& light : scene.lights) {
        light_position.push_back(light.position);
        light_radiance.push_back(light.color * light.intensity);
        light_attenuate.push_back(light.attenuate ? 1.0f : 0.0f);
    }
    if (!scene.lights.empty()) {
        const GLsizei count = static_cast<GLsizei>(scene.lights.size());
        glUniform3fv(glGetUniformLocation(p.program, "u_light_position"), count, &light_position[0][0]);
        glUniform3fv(glGetUniformLocation(p.program, "u_light_radiance"), count, &light_radiance[0][0]);
        glUniform1fv(glGetUniformLocation(p.program, "u_light_attenuate"), count, light_attenuate.data());
    }
    p.loc_base = glGetUniformLocation(p.program, "u_base");
    p.loc_ambient = glGetUniformLocation(p.program, "u_ambient");
    p.loc_diffuse = glGetUniformLocation(p.program, "u_diffuse");
    p.loc_specular = glGetUniformLocation(p.program, "u_specular");
    p.loc_exponent = glGetUniformLocation(p.program, "u_exponent");

    glEnableVertexAttribArray(0);
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), reinterpret_cast<const void*>(0));
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float),
                          reinterpret_cast<const void*>(3 * sizeof(float)));

    // raster: depth test with ties kept by the first triangle drawn (GL_LESS), counter-clockwise front faces,
    // culling only when the scene asks for it.
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glClearDepth(1.0);
    glFrontFace(GL_CCW);
    if (settings.cull_backfaces) {
        glEnable(GL_CULL_FACE);
        glCullFace(GL_BACK);
    } else {
        glDisable(GL_CULL_FACE);
    }
    glDisable(GL_DITHER);
    glClearColor(p.background.x, p.background.y, p.background.z, 1.0f);
    glViewport(0, 0, p.width, p.height);
    check_gl("setup");
}

LlvmpipePeer::~LlvmpipePeer() {
    Impl& p = *impl_;
    if (!p.context) return;
    if (OSMesaMakeCurrent(p.context, p.buffer.data(), GL_UNSIGNED_BYTE, p.width, p.height)) {
        p.release_fbo();
        if (p.program) glDeleteProgram(p.program);
        if (p.vbo) glDeleteBuffers(1, &p.vbo);
        if (p.ibo) glDeleteBuffers(1, &p.ibo);
    }
    OSMesaDestroyContext(p.context);
}

void LlvmpipePeer::set_samples(int samples) {
    Impl& p = *impl_;
    p.make_current();
    if (samples == p.samples) return;
    p.release_fbo();
    p.samples = 1;
    if (samples == 1) {
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        return;
    }
    GLint max_samples = 0;
    glGetIntegerv(GL_MAX_SAMPLES, &max_samples);
    if (samples < 1 || samples > max_samples)
        throw std::runtime_error("llvmpipe peer: " + std::to_string(samples) + " samples asked, llvmpipe offers " +
                                 std::to_string(max_samples));
    glGenRenderbuffers(1, &p.color_rb);
    glBindRenderbuffer(GL_RENDERBUFFER, p.color_rb);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_RGBA8, p.width, p.height);
    GLint granted = 0;
    glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_SAMPLES, &granted);
    glGenRenderbuffers(1, &p.depth_rb);
    glBindRenderbuffer(GL_RENDERBUFFER, p.depth_rb);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_DEPTH_COMPONENT24, p.width, p.height);
    glGenFramebuffers(1, &p.fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, p.fbo);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, p.color_rb);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, p.depth_rb);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw std::runtime_error("llvmpipe peer: the multisampled framebuffer is incomplete");
    if (granted != samples)
        throw std::runtime_error("llvmpipe peer: asked for " + std::to_string(samples) + " samples, got " +
                                 std::to_string(granted));
    check_gl("multisampled framebuffer");
    p.samples = samples;
}

int LlvmpipePeer::samples() const { return impl_->samples; }

void LlvmpipePeer::draw_frame() {
    Impl& p = *impl_;
    p.make_current();
    glBindFramebuffer(GL_FRAMEBUFFER, p.fbo);  // 0 (OSMesa's buffer) at 1 sample
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    for (const Impl::MeshDraw& draw : p.draws) {
        glUniform3fv(p.loc_base, 1, &draw.base[0]);
        glUniform3fv(p.loc_ambient, 1, &draw.ambient[0]);
        glUniform3fv(p.loc_diffuse, 1, &draw.diffuse[0]);
        glUniform3fv(p.loc_specular, 1, &draw.specular[0]);
        glUniform1f(p.loc_exponent, draw.exponent);
        glDrawElements(GL_TRIANGLES, draw.index_count, GL_UNSIGNED_INT,
                       reinterpret_cast<const void*>(draw.index_offset_bytes));
    }
    if (p.fbo) {
        glBindFramebuffer(GL_READ_FRAMEBUFFER, p.fbo);
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
        glBlitFramebuffer(0, 0, p.width, p.height, 0, 0, p.width, p.height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    }
    glFinish();
}

std::vector<uint8_t> LlvmpipePeer::image_top_down() const {
    const Impl& p = *impl_;
    const size_t row = static_cast<size_t>(p.width) * 4;
    std::vector<uint8_t> out(p.buffer.size());
    for (int y = 0; y < p.height; ++y)
        std::copy_n(p.buffer.data() + static_cast<size_t>(p.height - 1 - y) * row, row, out.data() + y * row);
    return out;
}

size_t LlvmpipePeer::triangles() const { return impl_->triangles; }

std::string LlvmpipePeer::renderer() const {
    impl_->make_current();
    const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    const auto* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
    return std::string(renderer ? renderer : "?") + ", " + (version ? version : "?");
}

}  // namespace raster_bench
