// The bug catalogue's faulty stage variants. Each wraps or replaces exactly one real stage and nothing else.
#include "tests/mutants/catalogue.h"

#include <cmath>
#include <limits>
#include <stdexcept>

#include <glm/geometric.hpp>

#include "raster/transform.h"

namespace raster::mutants {
namespace {

// --- clip ---------------------------------------------------------------------------------------------------

// "no near clipping": the side and far planes are clipped, the near plane is not, so vertices behind the eye
// (w <= 0) reach the divide.
ClippedPolygon clip_without_near(const glm::vec4& a, const glm::vec4& b, const glm::vec4& c, const ClipVolume& volume) {
    ClipVolume no_near = volume;
    no_near.near = -std::numeric_limits<float>::max();
    return clip_triangle(a, b, c, no_near);
}

// "triangles with w <= 0 dropped instead of clipped": any triangle reaching behind the near plane vanishes.
ClippedPolygon clip_dropping_near_crossers(const glm::vec4& a, const glm::vec4& b, const glm::vec4& c,
                                           const ClipVolume& volume) {
    if (a.w < volume.near || b.w < volume.near || c.w < volume.near) return {};
    return clip_triangle(a, b, c, volume);
}

// --- setup --------------------------------------------------------------------------------------------------

// "no fill rule": samples exactly on an edge are inside for every triangle, so shared edges are covered twice.
int setup_without_fill_rule(const ClippedPolygon& polygon, uint32_t id, const SetupParams& params,
                            std::vector<TriangleSetup>& out) {
    const size_t first = out.size();
    const int added = setup_polygon(polygon, id, params, out);
    for (size_t i = first; i < out.size(); ++i)
        for (int64_t& bias : out[i].bias) bias = 0;
    return added;
}

// "cracks on shared edges": samples exactly on an edge are outside for every triangle.
int setup_with_cracks(const ClippedPolygon& polygon, uint32_t id, const SetupParams& params,
                      std::vector<TriangleSetup>& out) {
    const size_t first = out.size();
    const int added = setup_polygon(polygon, id, params, out);
    for (size_t i = first; i < out.size(); ++i)
        for (int64_t& bias : out[i].bias) bias = -1;
    return added;
}

// "sub-pixel triangles discarded (det < 1)": triangles smaller than one square pixel are thrown away.
int setup_discarding_sub_pixel(const ClippedPolygon& polygon, uint32_t id, const SetupParams& params,
                               std::vector<TriangleSetup>& out) {
    const size_t first = out.size();
    setup_polygon(polygon, id, params, out);
    const int fixed_bits = fixed_bits_for(params.snap_bits);
    const int64_t one_pixel_area2 = int64_t{2} << (2 * fixed_bits);
    size_t kept = first;
    for (size_t i = first; i < out.size(); ++i)
        if (out[i].area2 >= one_pixel_area2) out[kept++] = out[i];
    out.resize(kept);
    return static_cast<int>(kept - first);
}

// "y not flipped": NDC y goes to screen y unflipped, so the image comes out upside down.
int setup_without_y_flip(const ClippedPolygon& polygon, uint32_t id, const SetupParams& params,
                         std::vector<TriangleSetup>& out) {
    ClippedPolygon flipped = polygon;
    for (int i = 0; i < flipped.count; ++i) flipped.vertices[i].position.y = -flipped.vertices[i].position.y;
    return setup_polygon(flipped, id, params, out);
}

// --- rasterize ----------------------------------------------------------------------------------------------

// "affine instead of perspective-correct": attributes are interpolated linearly in screen space (every vertex
// weighted as if w were 1), so textures and colours swim and view depth is wrong.
void rasterize_affine(const std::vector<TriangleSetup>& triangles, const RasterParams& params, VisibilityBuffer& out) {
    std::vector<TriangleSetup> affine = triangles;
    for (TriangleSetup& t : affine)
        for (float& inv_w : t.inv_w) inv_w = 1.0f;
    rasterize(affine, params, out);
}

// "depth buffer initialised with numeric_limits<float>::min()": with a conventional less-than test on
// d' = 1 - d (0 at near), the cleared value min() ~ 1e-38 is nearer than every surface, so nothing survives
// but fragments exactly on the near plane.
void rasterize_with_depth_cleared_to_min(const std::vector<TriangleSetup>& triangles, const RasterParams& params,
                                         VisibilityBuffer& out) {
    rasterize(triangles, params, out);
    for (size_t i = 0; i < out.size(); ++i) {
        if (out.triangle[i] == kNoTriangle) continue;
        out.triangle[i] = kNoTriangle;  // 1 - d >= min() for every d < 1: the fragment fails "1 - d < min()"
        out.bary[i] = glm::vec3(0.0f);
        out.view_depth[i] = 0.0f;
    }
}

// --- sample positions ---------------------------------------------------------------------------------------

// "wrong sample positions": samples taken half a pixel off (at pixel corners instead of centres, the classic
// missing +0.5), wrapped back into the pixel.
std::vector<glm::vec2> sample_offsets_half_pixel_off(int samples, SamplePattern pattern) {
    std::vector<glm::vec2> offsets = sample_offsets(samples, pattern);
    for (glm::vec2& o : offsets) o = glm::fract(o + 0.5f);
    return offsets;
}

// --- vertex stage -------------------------------------------------------------------------------------------

// "integer-divided aspect ratio": width / height computed in integers (640 / 480 = 1), so the image is
// stretched horizontally.
TransformedScene vertex_with_integer_aspect(const Scene& scene, const VertexStageNeeds& needs) {
    const int aspect = scene.settings.width / scene.settings.height;
    return run_vertex_stage(scene, needs, view_matrix(scene.camera),
                            perspective_matrix(scene.camera.fov_y_degrees, static_cast<float>(aspect),
                                               scene.camera.near, scene.camera.far));
}

// "normals not transformed by the inverse-transpose": mesh normals are transformed by the model matrix itself,
// which tilts them under non-uniform scale.
TransformedScene vertex_with_model_matrix_normals(const Scene& scene, const VertexStageNeeds& needs) {
    TransformedScene out = run_vertex_stage(scene, needs);
    if (!needs.vertex_normals) return out;
    for (uint32_t mesh = 0; mesh < scene.meshes.size(); ++mesh) {
        const MeshData& data = scene.meshes[mesh].data;
        if (data.normals.size() != data.positions.size()) continue;
        const glm::mat3 model(scene.meshes[mesh].model);
        for (size_t i = 0; i < data.normals.size(); ++i) {
            const glm::vec3 n = model * data.normals[i];
            const float length = glm::length(n);
            out.world_normal[out.mesh_first_vertex[mesh] + i] = length > 0.0f ? n / length : glm::vec3(0.0f);
        }
    }
    return out;
}

// --- lighting -----------------------------------------------------------------------------------------------

// "1/r^2 attenuation missing": lights marked as attenuating shine as if they were not.
LightingTerms lighting_without_attenuation(const glm::vec3& position, const glm::vec3& normal, const glm::vec3& to_eye,
                                           const Material& material, const std::vector<Light>& lights,
                                           const glm::vec3& ambient_light, SpecularModel model) {
    std::vector<Light> unattenuated = lights;
    for (Light& light : unattenuated) light.attenuate = false;
    return evaluate_lighting(position, normal, to_eye, material, unattenuated, ambient_light, model);
}

std::vector<Mutant> build_catalogue() {
    std::vector<Mutant> list;
    auto add = [&](const char* name, const char* stage, const char* symptom, auto&& replace) {
        Mutant m{name, stage, symptom, PipelineStages{}};
        replace(m.stages);
        list.push_back(std::move(m));
    };
    add("no near clipping", "clip", "vertices behind the eye reach the divide",
        [](PipelineStages& s) { s.clip = clip_without_near; });
    add("w <= 0 dropped instead of clipped", "clip", "triangles crossing the near plane vanish",
        [](PipelineStages& s) { s.clip = clip_dropping_near_crossers; });
    add("no fill rule", "setup", "samples on shared edges are covered twice",
        [](PipelineStages& s) { s.setup = setup_without_fill_rule; });
    add("cracks on shared edges", "setup", "samples on shared edges are covered by neither triangle",
        [](PipelineStages& s) { s.setup = setup_with_cracks; });
    add("sub-pixel triangles discarded", "setup", "triangles under one square pixel are dropped",
        [](PipelineStages& s) { s.setup = setup_discarding_sub_pixel; });
    add("y not flipped", "setup", "the image is upside down",
        [](PipelineStages& s) { s.setup = setup_without_y_flip; });
    add("affine instead of perspective-correct", "rasterize", "attributes interpolate linearly in screen space",
        [](PipelineStages& s) { s.rasterize = rasterize_affine; });
    add("depth buffer initialised with numeric_limits<float>::min()", "rasterize", "every fragment fails the depth test",
        [](PipelineStages& s) { s.rasterize = rasterize_with_depth_cleared_to_min; });
    add("wrong sample positions", "sample positions", "samples are half a pixel off",
        [](PipelineStages& s) { s.sample_offsets = sample_offsets_half_pixel_off; });
    add("integer-divided aspect ratio", "vertex", "the image is stretched horizontally",
        [](PipelineStages& s) { s.vertex = vertex_with_integer_aspect; });
    add("normals not transformed by the inverse-transpose", "vertex", "normals tilt under non-uniform scale",
        [](PipelineStages& s) { s.vertex = vertex_with_model_matrix_normals; });
    add("1/r^2 attenuation missing", "lighting", "attenuating lights shine at full strength",
        [](PipelineStages& s) { s.lighting = lighting_without_attenuation; });
    return list;
}

}  // namespace

const std::vector<Mutant>& catalogue() {
    static const std::vector<Mutant> list = build_catalogue();
    return list;
}

const Mutant& mutant(const std::string& name) {
    for (const Mutant& m : catalogue())
        if (m.name == name) return m;
    throw std::out_of_range("no mutant named '" + name + "'");
}

}  // namespace raster::mutants
