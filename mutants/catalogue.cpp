// The bug catalogue's faulty variants: each wraps or replaces exactly one real stage or building block, nothing else.
#include "mutants/catalogue.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <glm/geometric.hpp>

#include "raster/core/conventions.h"
#include "raster/pipeline/sample_pattern.h"
#include "raster/core/transform.h"

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

// "side planes not clipped (vertices clamped instead)": only near and far cut the triangle; a vertex off screen
// reaches setup, which clamps it to the viewport border and so squashes the triangle. Emulated by clipping a copy
// whose x and y are scaled down by a power of two (exact) until no side plane can cut, then scaling back.
ClippedPolygon clip_without_side_planes(const glm::vec4& a, const glm::vec4& b, const glm::vec4& c,
                                        const ClipVolume& volume) {
    const double largest = std::max({std::fabs(a.x), std::fabs(a.y), std::fabs(b.x), std::fabs(b.y),
                                     std::fabs(c.x), std::fabs(c.y)});
    if (!std::isfinite(largest) || largest == 0.0) return clip_triangle(a, b, c, volume);
    int exponent = 0;
    std::frexp(largest / static_cast<double>(volume.near), &exponent);  // largest < near * 2^exponent
    const int shift = exponent + 1;                                       // so |x| * 2^-shift < near / 2 <= w / 2
    auto squeeze = [&](glm::vec4 p) {
        p.x = std::ldexp(p.x, -shift);
        p.y = std::ldexp(p.y, -shift);
        return p;
    };
    ClippedPolygon polygon = clip_triangle(squeeze(a), squeeze(b), squeeze(c), volume);
    for (int i = 0; i < polygon.count; ++i) {
        polygon.vertices[i].position.x = std::ldexp(polygon.vertices[i].position.x, shift);
        polygon.vertices[i].position.y = std::ldexp(polygon.vertices[i].position.y, shift);
    }
    return polygon;
}

// "near and far tested with a strict inequality": a vertex exactly on the near or far plane counts as outside,
// so a triangle touching a plane is clipped (new vertices, `clipped` set) instead of passed through untouched.
// In floats, w > near is exactly w >= nextafter(near, +inf).
ClippedPolygon clip_with_strict_near_far(const glm::vec4& a, const glm::vec4& b, const glm::vec4& c,
                                         const ClipVolume& volume) {
    ClipVolume strict = volume;
    strict.near = std::nextafter(volume.near, std::numeric_limits<float>::infinity());
    strict.far = std::nextafter(volume.far, 0.0f);
    return clip_triangle(a, b, c, strict);
}

// "NaN slips through the clip test": without the finiteness check, NaN compares false against every plane, so a
// triangle with a NaN coordinate has an empty outcode and goes to setup untouched.
ClippedPolygon clip_letting_nan_through(const glm::vec4& a, const glm::vec4& b, const glm::vec4& c,
                                        const ClipVolume& volume) {
    auto has_nan = [](const glm::vec4& p) {
        return std::isnan(p.x) || std::isnan(p.y) || std::isnan(p.z) || std::isnan(p.w);
    };
    if (!has_nan(a) && !has_nan(b) && !has_nan(c)) return clip_triangle(a, b, c, volume);
    ClippedPolygon polygon;
    polygon.count = 3;
    polygon.vertices[0] = {a, {1.0f, 0.0f, 0.0f}};
    polygon.vertices[1] = {b, {0.0f, 1.0f, 0.0f}};
    polygon.vertices[2] = {c, {0.0f, 0.0f, 1.0f}};
    return polygon;
}

// --- setup --------------------------------------------------------------------------------------------------

// Runs the real setup, then lets `fault` alter each triangle it appended: the shape of most setup mutants.
template <class Fault>
int setup_then(const ClippedPolygon& polygon, uint32_t id, const FrameParams& params, std::vector<TriangleSetup>& out,
               Fault fault) {
    const size_t first = out.size();
    const int added = setup_polygon(polygon, id, params, out);
    for (size_t k = first; k < out.size(); ++k) fault(out[k]);
    return added;
}

// "no fill rule": samples exactly on an edge are inside for every triangle, so shared edges are covered twice.
int setup_without_fill_rule(const ClippedPolygon& polygon, uint32_t id, const FrameParams& params,
                            std::vector<TriangleSetup>& out) {
    return setup_then(polygon, id, params, out, [](TriangleSetup& t) {
        for (int64_t& bias : t.bias) bias = 0;
    });
}

// "cracks on shared edges": samples exactly on an edge are outside for every triangle.
int setup_with_cracks(const ClippedPolygon& polygon, uint32_t id, const FrameParams& params,
                      std::vector<TriangleSetup>& out) {
    return setup_then(polygon, id, params, out, [](TriangleSetup& t) {
        for (int64_t& bias : t.bias) bias = -1;
    });
}

// "float edge functions": the edge equations are set up in float (24-bit mantissa), so c = dy * x - dx * y is
// rounded; two triangles sharing an edge round it differently and the edge cracks or doubles. That is the
// EdgeArithmetic::float32 mode, forced on whatever the scene asks for.
int setup_with_float_edges(const ClippedPolygon& polygon, uint32_t id, const FrameParams& params,
                           std::vector<TriangleSetup>& out) {
    FrameParams float_edges = params;
    float_edges.edges = EdgeArithmetic::float32;
    return setup_polygon(polygon, id, float_edges, out);
}

// "fill rule inverted (bottom-right)": samples on an edge belong to the triangle when the edge is a bottom or right
// edge. Still watertight, but every shared sample goes to the other triangle.
int setup_with_bottom_right_rule(const ClippedPolygon& polygon, uint32_t id, const FrameParams& params,
                                 std::vector<TriangleSetup>& out) {
    return setup_then(polygon, id, params, out, [](TriangleSetup& t) {
        for (int i = 0; i < 3; ++i) {
            const int s = (i + 1) % 3, e = (i + 2) % 3;
            t.bias[i] = is_top_left(t.x[e] - t.x[s], t.y[e] - t.y[s]) ? -1 : 0;
        }
    });
}

// "sub-pixel triangles discarded (det < 1)": triangles smaller than one square pixel are thrown away.
int setup_discarding_sub_pixel(const ClippedPolygon& polygon, uint32_t id, const FrameParams& params,
                               std::vector<TriangleSetup>& out) {
    const size_t first = out.size();
    setup_polygon(polygon, id, params, out);
    const int fixed_bits = params.fixed_bits;
    const int64_t one_pixel_area2 = int64_t{2} << (2 * fixed_bits);
    size_t kept = first;
    for (size_t i = first; i < out.size(); ++i)
        if (out[i].area2 >= one_pixel_area2) out[kept++] = out[i];
    out.resize(kept);
    return static_cast<int>(kept - first);
}

// "y not flipped": NDC y goes to screen y unflipped, so the image comes out upside down.
int setup_without_y_flip(const ClippedPolygon& polygon, uint32_t id, const FrameParams& params,
                         std::vector<TriangleSetup>& out) {
    ClippedPolygon flipped = polygon;
    for (int i = 0; i < flipped.count; ++i) flipped.vertices[i].position.y = -flipped.vertices[i].position.y;
    return setup_polygon(flipped, id, params, out);
}

// "front faces culled (winding inverted)": culling keeps the faces turned away from the eye, so a closed mesh shows
// its inside.
bool faces_front_inverted(const glm::vec4& a, const glm::vec4& b, const glm::vec4& c) { return !faces_front(a, b, c); }

// --- rasterize ----------------------------------------------------------------------------------------------

// "affine instead of perspective-correct": attributes are interpolated linearly in screen space (every vertex
// weighted as if w were 1), so textures and colours swim and view depth is wrong.
void rasterize_affine(const std::vector<TriangleSetup>& triangles, const FrameParams& params, VisibilityBuffer& out) {
    std::vector<TriangleSetup> affine = triangles;
    for (TriangleSetup& t : affine) t.affine = true;  // the Interpolation::affine mode, forced
    rasterize_reference(affine, params, out);
}

// "depth buffer initialised with numeric_limits<float>::min()": with a conventional less-than test on
// d' = 1 - d (0 at near), the cleared value min() ~ 1e-38 is nearer than every surface, so nothing survives
// but fragments exactly on the near plane.
void rasterize_with_depth_cleared_to_min(const std::vector<TriangleSetup>& triangles, const FrameParams& params,
                                         VisibilityBuffer& out) {
    rasterize_reference(triangles, params, out);
    for (size_t i = 0; i < out.size(); ++i) {
        if (out.triangle[i] == kNoTriangle) continue;
        out.triangle[i] = kNoTriangle;  // 1 - d >= min() for every d < 1: the fragment fails "1 - d < min()"
        out.bary[i] = glm::vec3(0.0f);
        out.view_depth[i] = 0.0f;
    }
}

// Runs the real rasterizer with each setup's id replaced by its index, so every sample names its winning setup,
// then lets `resolve(setup, X, Y, pixel_x, pixel_y, fixed_bits, bary, view_depth)` write the sample's entry: the
// shape of a rasterizer whose coverage and depth test are right but whose resolve is faulty.
template <class Resolve>
void rasterize_with_resolve(const std::vector<TriangleSetup>& triangles, const FrameParams& params,
                            VisibilityBuffer& out, Resolve resolve) {
    std::vector<TriangleSetup> indexed = triangles;
    for (size_t i = 0; i < indexed.size(); ++i) indexed[i].triangle_id = static_cast<uint32_t>(i);
    rasterize_reference(indexed, params, out);
    const int fixed_bits = params.fixed_bits;
    const FixedSampleOffsets& offsets = params.fixed_offsets;
    for (int y = 0; y < out.height; ++y)
        for (int x = 0; x < out.width; ++x)
            for (int s = 0; s < out.samples; ++s) {
                const size_t at = out.index(x, y, s);
                if (out.triangle[at] == kNoTriangle) continue;
                const TriangleSetup& t = triangles[out.triangle[at]];
                const int64_t X = (int64_t{x} << fixed_bits) + offsets.x[s];
                const int64_t Y = (int64_t{y} << fixed_bits) + offsets.y[s];
                resolve(t, X, Y, x, y, fixed_bits, out.bary[at], out.view_depth[at]);
                out.triangle[at] = t.triangle_id;
            }
}

// Screen-space barycentrics E_i / area2 of a setup at (X, Y).
glm::dvec3 screen_barycentrics(const TriangleSetup& t, int64_t X, int64_t Y) {
    glm::dvec3 l;
    for (int i = 0; i < 3; ++i)
        l[i] = static_cast<double>(t.a[i] * X + t.b[i] * Y + t.c[i]) / static_cast<double>(t.area2);
    return l;
}

// "view depth interpolated linearly (w instead of 1/w)": the sample's w is the screen-space interpolation of the
// vertices' w, and the perspective weights l_i / w_i are scaled by it without renormalising, so the barycentrics
// no longer sum to 1 and the depth is too large inside the triangle.
void rasterize_with_linear_w(const std::vector<TriangleSetup>& triangles, const FrameParams& params,
                             VisibilityBuffer& out) {
    rasterize_with_resolve(triangles, params, out,
                           [](const TriangleSetup& t, int64_t X, int64_t Y, int, int, int, glm::vec3& bary, float& depth) {
                               const glm::dvec3 l = screen_barycentrics(t, X, Y);
                               double w = 0.0;
                               for (int i = 0; i < 3; ++i) w += l[i] / static_cast<double>(t.inv_w[i]);
                               glm::dvec3 b(0.0);
                               for (int i = 0; i < 3; ++i) b += l[i] * static_cast<double>(t.inv_w[i]) * w * glm::dvec3(t.bary[i]);
                               bary = glm::vec3(b);
                               depth = static_cast<float>(w);
                           });
}

// "barycentrics evaluated at the pixel centre": coverage is tested at each sample, but the attributes of every
// sample are interpolated at its pixel's centre, which may lie outside the triangle (negative barycentrics).
void rasterize_with_pixel_centre_barycentrics(const std::vector<TriangleSetup>& triangles, const FrameParams& params,
                                              VisibilityBuffer& out) {
    rasterize_with_resolve(triangles, params, out,
                           [](const TriangleSetup& t, int64_t, int64_t, int x, int y, int fixed_bits, glm::vec3& bary,
                              float& depth) {
                               const int64_t half = int64_t{1} << (fixed_bits - 1);
                               const glm::dvec3 l = screen_barycentrics(t, (int64_t{x} << fixed_bits) + half,
                                                                        (int64_t{y} << fixed_bits) + half);
                               double weight[3], total = 0.0;
                               for (int i = 0; i < 3; ++i) total += weight[i] = l[i] * static_cast<double>(t.inv_w[i]);
                               glm::dvec3 b(0.0);
                               for (int i = 0; i < 3; ++i) b += (weight[i] / total) * glm::dvec3(t.bary[i]);
                               bary = glm::vec3(b);
                               depth = static_cast<float>(1.0 / total);
                           });
}

// "no depth test (the first triangle drawn stays)": every fragment gets the same depth, so wherever triangles
// overlap the draw order decides, not the distance.
void rasterize_without_depth_test(const std::vector<TriangleSetup>& triangles, const FrameParams& params,
                                  VisibilityBuffer& out) {
    std::vector<TriangleSetup> flat = triangles;
    for (TriangleSetup& t : flat)
        for (double& d : t.depth) d = 0.5;
    rasterize_reference(flat, params, out);
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

// --- building blocks (and the vertex stage that uses them) -----------------------------------------------------

// "look-at basis not orthonormal": the camera's up vector is used as its y axis as given, instead of being
// re-orthogonalised (v = w x u), so the view matrix shears whenever up is not perpendicular to the view direction.
glm::mat4 look_at_with_raw_up(const glm::vec3& eye, const glm::vec3& target, const glm::vec3& up) {
    const glm::vec3 w = glm::normalize(eye - target);
    const glm::vec3 u = glm::normalize(glm::cross(up, w));
    const glm::vec3 v = glm::normalize(up);
    glm::mat4 m(1.0f);
    m[0][0] = u.x; m[1][0] = u.y; m[2][0] = u.z; m[3][0] = -glm::dot(u, eye);
    m[0][1] = v.x; m[1][1] = v.y; m[2][1] = v.z; m[3][1] = -glm::dot(v, eye);
    m[0][2] = w.x; m[1][2] = w.y; m[2][2] = w.z; m[3][2] = -glm::dot(w, eye);
    return m;
}

TransformedScene vertex_with_raw_up(const Scene& scene, const VertexStageNeeds& needs) {
    const Camera& camera = scene.camera;
    return run_vertex_stage(scene, needs, look_at_with_raw_up(camera.eye, camera.target, camera.up),
                            projection_matrix(camera, scene.settings.width, scene.settings.height));
}

// "OpenGL [-1, 1] depth mapping": the projection's depth row is OpenGL's (near -> -1, far -> +1, written in float)
// while the depth test keeps the larger value, so the farthest surface wins; at near = 1e-6, far = 1e9 the
// factor (f + n) / (f - n) rounds to 1 and depth collapses.
glm::mat4 perspective_with_opengl_depth(float fov_y_degrees, float aspect, float near, float far) {
    glm::mat4 m = perspective_matrix(fov_y_degrees, aspect, near, far);
    m[2][2] = -(far + near) / (far - near);
    m[3][2] = -2.0f * far * near / (far - near);
    return m;
}

TransformedScene vertex_with_opengl_depth(const Scene& scene, const VertexStageNeeds& needs) {
    const Camera& camera = scene.camera;
    const float aspect = static_cast<float>(scene.settings.width) / static_cast<float>(scene.settings.height);
    return run_vertex_stage(scene, needs, view_matrix(camera),
                            perspective_with_opengl_depth(camera.fov_y_degrees, aspect, camera.near, camera.far));
}

// "model matrix multiplied in the wrong order": each step of the transform chain is multiplied on the right
// (model = model * step) instead of the left, so scale-rotate-translate becomes S * R * T.
glm::mat4 model_matrix_composed_backwards(const ScaleRotateTranslate& chain) {
    glm::mat4 model(1.0f);
    for (const glm::mat4& step : {scale_matrix(chain.scale), rotate_matrix(chain.degrees, chain.axis),
                                  translate_matrix(chain.offset)})
        model = model * step;
    return model;
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
        Mutant m{name, stage, symptom, PipelineStages{}, BuildingBlocks{}};
        replace(m.stages);
        list.push_back(std::move(m));
    };
    // A fault in the reference rasterizer shows only on the reference renderer, the one that runs it.
    auto add_reference = [&](const char* name, const char* stage, const char* symptom, auto&& replace) {
        Mutant m{name, stage, symptom, PipelineStages{}, BuildingBlocks{}, RasterPath::reference};
        replace(m.stages);
        list.push_back(std::move(m));
    };
    auto add_block = [&](const char* name, const char* stage, const char* symptom, auto&& replace) {
        Mutant m{name, stage, symptom, PipelineStages{}, BuildingBlocks{}};
        replace(m.stages, m.blocks);
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
    add_reference("affine instead of perspective-correct", "rasterize",
                  "attributes interpolate linearly in screen space",
                  [](PipelineStages& s) { s.reference_rasterize = rasterize_affine; });
    add_reference("depth buffer initialised with numeric_limits<float>::min()", "rasterize",
                  "every fragment fails the depth test",
                  [](PipelineStages& s) { s.reference_rasterize = rasterize_with_depth_cleared_to_min; });
    add("wrong sample positions", "sample positions", "samples are half a pixel off",
        [](PipelineStages& s) { s.sample_offsets = sample_offsets_half_pixel_off; });
    add("integer-divided aspect ratio", "vertex", "the image is stretched horizontally",
        [](PipelineStages& s) { s.vertex = vertex_with_integer_aspect; });
    add("normals not transformed by the inverse-transpose", "vertex", "normals tilt under non-uniform scale",
        [](PipelineStages& s) { s.vertex = vertex_with_model_matrix_normals; });
    add("1/r^2 attenuation missing", "lighting", "attenuating lights shine at full strength",
        [](PipelineStages& s) { s.lighting = lighting_without_attenuation; });
    add("float edge functions", "setup", "edge equations rounded to float crack or double shared edges",
        [](PipelineStages& s) { s.setup = setup_with_float_edges; });
    add_block("model matrix multiplied in the wrong order", "model transform chain",
              "a scale-rotate-translate chain becomes S * R * T, so scaled objects fly off",
              [](PipelineStages&, BuildingBlocks& b) { b.model_matrix = model_matrix_composed_backwards; });
    add("front faces culled (winding inverted)", "setup", "with culling on, a closed mesh shows its inside",
        [](PipelineStages& s) { s.faces_front = faces_front_inverted; });
    add("fill rule inverted (bottom-right)", "setup", "shared samples go to the triangle below or right of the edge",
        [](PipelineStages& s) { s.setup = setup_with_bottom_right_rule; });
    add("side planes not clipped (vertices clamped instead)", "clip",
        "triangles reaching off screen are squashed against the border",
        [](PipelineStages& s) { s.clip = clip_without_side_planes; });
    add("near and far tested with a strict inequality", "clip",
        "a triangle touching the near or far plane is needlessly clipped",
        [](PipelineStages& s) { s.clip = clip_with_strict_near_far; });
    add("NaN slips through the clip test", "clip", "a triangle with a NaN vertex reaches setup and covers samples",
        [](PipelineStages& s) { s.clip = clip_letting_nan_through; });
    add_reference("view depth interpolated linearly (w instead of 1/w)", "rasterize",
                  "barycentrics do not sum to 1 and depths bulge away from the camera",
                  [](PipelineStages& s) { s.reference_rasterize = rasterize_with_linear_w; });
    add_reference("barycentrics evaluated at the pixel centre", "rasterize",
                  "samples near an edge extrapolate attributes (negative barycentrics)",
                  [](PipelineStages& s) { s.reference_rasterize = rasterize_with_pixel_centre_barycentrics; });
    add_reference("no depth test (the first triangle drawn stays)", "rasterize",
                  "draw order, not distance, decides visibility",
                  [](PipelineStages& s) { s.reference_rasterize = rasterize_without_depth_test; });
    add_block("look-at basis not orthonormal", "look-at matrix", "the view shears when up is not perpendicular",
              [](PipelineStages& s, BuildingBlocks& b) {
                  b.look_at = look_at_with_raw_up;
                  s.vertex = vertex_with_raw_up;
              });
    add_block("OpenGL [-1, 1] depth mapping", "projection matrix",
              "the z-buffer keeps the farthest surface and depth collapses at extreme near/far",
              [](PipelineStages& s, BuildingBlocks& b) {
                  b.perspective = perspective_with_opengl_depth;
                  s.vertex = vertex_with_opengl_depth;
              });
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
