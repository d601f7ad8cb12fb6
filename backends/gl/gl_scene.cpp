// The scene as the GL backend draws it (gl_scene.h).
#include "backends/gl/gl_scene.h"

#include <cstdint>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include "raster/transform/model_matrix.h"

namespace raster::gl {
namespace {

constexpr size_t kMaxLights = 8;  // the fragment shader's light array

glm::vec3 unit_or_zero(const glm::vec3& v) {
    const float length = glm::length(v);
    return length > 0.0f ? v / length : glm::vec3(0.0f);
}

}  // namespace

std::string unsupported_by_gl(const Scene& scene) {
    std::string what;
    const auto add = [&what](const std::string& item) { what += (what.empty() ? "" : ", ") + item; };
    const ShadingMode mode = scene.settings.shading;
    if (mode != ShadingMode::unlit && mode != ShadingMode::phong && mode != ShadingMode::blinn_phong)
        add(std::string(to_string(mode)) + " shading (it draws unlit, phong and blinn-phong)");
    bool textured = false, blended = false;
    for (const SceneMesh& mesh : scene.meshes)
        for_each_material(mesh, [&](const Material& material) {
            textured |= material.texture.has_value();
            blended |= is_blended(material);
        });
    if (textured) add("textures");
    if (blended) add("transparency");
    if (has_shadows(scene) && mode != ShadingMode::unlit) add("shadows");
    if (scene.lights.size() > kMaxLights) add("more than " + std::to_string(kMaxLights) + " lights");
    const RenderSettings& settings = scene.settings;
    if (settings.pattern != SamplePattern::standard) add("the grid sample pattern");
    if (settings.samples != 1 && settings.samples != 4) add(std::to_string(settings.samples) + " samples (it draws 1 or 4)");
    if (settings.msaa) add("MSAA (raster shades at a pixel's first covered sample, GL at its centre)");
    if (settings.snap_bits != 8) add(std::to_string(settings.snap_bits) + " sub-pixel bits (llvmpipe snaps to 8)");
    if (!exact_precision(settings.modes))
        add("the precision modes (--edges, --interpolation, --depth-format, --clipping)");
    if (settings.resolution_divisor != 1) add("a reduced resolution (--resolution-divisor)");
    // Reversed-Z depth at view depth v is near (far - v) / (v (far - near)): about near / v, and smallest just short
    // of the far plane, where far - v is at least a float step of far (2^-24 far), so about 2^-24 near / far. Below
    // 2^-126 it is subnormal, and llvmpipe flushes subnormal depth to 0, the cleared far value, which GL_GREATER
    // never passes (docs/gl.md, finding 3): near / far must be at least 2^-102, 2^-100 with a margin.
    if (scene.camera.projection == Projection::perspective && scene.camera.near < scene.camera.far * 0x1p-100f)
        add("a near plane below far / 2^100 (reversed-Z depth would be subnormal, which llvmpipe flushes to zero)");
    // Its read backs hold 16 bytes a sample in one GL call, whose size is a 32-bit int.
    const uint64_t samples = uint64_t(settings.width) * uint64_t(settings.height) * uint64_t(settings.samples);
    if (samples * 16 > uint64_t(INT32_MAX)) add("frames over " + std::to_string(INT32_MAX / 16) + " samples");
    return what;
}

Scene gl_drawable(Scene scene) {
    RenderSettings& settings = scene.settings;
    const ShadingMode mode = settings.shading;
    if (mode != ShadingMode::unlit && mode != ShadingMode::phong && mode != ShadingMode::blinn_phong)
        settings.shading = ShadingMode::blinn_phong;
    settings.samples = settings.samples > 1 ? 4 : 1;
    settings.pattern = SamplePattern::standard;
    settings.msaa = false;
    settings.snap_bits = 8;
    settings.modes = PrecisionModes{};
    settings.resolution_divisor = 1;
    for (SceneMesh& mesh : scene.meshes)
        for_each_material(mesh, [](Material& material) {
            material.texture.reset();
            material.opacity = 1.0f;
        });
    for (Light& light : scene.lights) light.shadows = false;
    if (scene.lights.size() > kMaxLights) scene.lights.resize(kMaxLights);
    return scene;
}

GlScene gl_scene(const Scene& scene) {
    GlScene out;
    const bool lit = scene.settings.shading != ShadingMode::unlit;
    for (const SceneMesh& mesh : scene.meshes) {
        const MeshData& data = *mesh.data;
        const glm::mat4 model = model_matrix(mesh.transform);
        std::vector<glm::vec3> world(data.positions.size());
        for (size_t i = 0; i < world.size(); ++i) world[i] = glm::vec3(model * glm::vec4(data.positions[i], 1.0f));
        std::vector<glm::vec3> normals(data.positions.size(), glm::vec3(0.0f));
        if (lit && data.normals.size() == data.positions.size()) {
            const glm::mat3 to_world = glm::transpose(glm::inverse(glm::mat3(model)));
            for (size_t i = 0; i < normals.size(); ++i) normals[i] = unit_or_zero(to_world * data.normals[i]);
        } else if (lit) {
            for (const TriangleIndices& t : data.triangles) {
                const glm::vec3 n = unit_or_zero(
                    glm::cross(world[t.v[1]] - world[t.v[0]], world[t.v[2]] - world[t.v[0]]));
                for (uint32_t corner : t.v) normals[corner] += n;
            }
            for (glm::vec3& n : normals) n = unit_or_zero(n);
        }
        for (uint32_t triangle = 0; triangle < data.triangles.size(); ++triangle) {
            const Material& material = material_of(mesh, triangle);
            if (out.draws.empty() || out.draws.back().material != &material)
                out.draws.push_back({static_cast<uint32_t>(out.corners.size()), 0, &material});
            const TriangleIndices& t = data.triangles[triangle];
            for (uint32_t corner : t.v) {
                const glm::vec3 colour = !data.face_colors.empty() ? data.face_colors[triangle]
                                         : !data.colors.empty()    ? data.colors[corner]
                                                                   : material.color;
                out.corners.push_back({world[corner], normals[corner], colour});
            }
            out.draws.back().corners += 3;
        }
    }
    return out;
}

}  // namespace raster::gl
