// Seed 001 balboa scenes: the shared camera and settings, the single triangle of part 2.1, and the JSON scene of
// section 4 (camera transform, background, objects inline or from PLY files, transform lists).
#include "raster/compat/scene_format_seed001.h"

#include <cmath>
#include <cstdio>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "raster/scene/validation.h"
#include "raster/compat/seed_scene_readers.h"
#include "raster/transform/model_matrix.h"

namespace raster {
namespace {

float field_of_view_degrees(float s) { return float(2.0 * std::atan(double(s)) * (180.0 / M_PI)); }

}  // namespace

std::string seed001_camera_problem(float s, float z_near) {
    char text[160];
    if (!(s > 0.0f) || !std::isfinite(s) || !(field_of_view_degrees(s) < 180.0f)) {
        std::snprintf(text, sizeof text, "s must be a positive number (half the image plane's height), got %g", s);
        return text;
    }
    if (!(z_near > 0.0f) || !(z_near < kSeed001Far)) {
        std::snprintf(text, sizeof text, "z_near must be > 0 and < %g, got %g", kSeed001Far, z_near);
        return text;
    }
    return "";
}

void set_seed001_camera(float s, float z_near, Scene& scene) {
    scene.camera.eye = glm::vec3(0.0f);
    scene.camera.target = glm::vec3(0.0f, 0.0f, -1.0f);
    scene.camera.up = glm::vec3(0.0f, 1.0f, 0.0f);
    scene.camera.fov_y_degrees = field_of_view_degrees(s);
    scene.camera.near = z_near;
    scene.camera.far = kSeed001Far;
    scene.settings.samples = 16;
    scene.settings.pattern = SamplePattern::grid;  // "a 4x4 supersampling", as in homework 1
    scene.settings.shading = ShadingMode::unlit;
    scene.settings.cull_backfaces = false;
}

Scene seed001_triangle_scene(const Seed001Triangle& triangle) {
    Scene scene;
    scene.path = "balboa -hw 2_1";
    scene.settings.width = kSeed001DefaultWidth;
    scene.settings.height = kSeed001DefaultHeight;
    scene.settings.background = glm::vec3(kSeed001Background);
    set_seed001_camera(triangle.s, triangle.z_near, scene);
    SceneMesh mesh;
    mesh.source = "-p0 -p1 -p2";
    MeshData& data = mutable_data(mesh);
    data.positions.assign(triangle.vertices.begin(), triangle.vertices.end());
    data.triangles.push_back({{0, 1, 2}});
    data.face_colors.push_back(triangle.color);
    scene.meshes.push_back(std::move(mesh));
    return scene;
}

namespace {

void warn_unknown_keys(const Node& map, const DocumentReader& reader, std::initializer_list<const char*> known,
                       const char* where) {
    if (std::string unknown = reader.unknown_keys(map, known); !unknown.empty())
        std::fprintf(stderr, "%s:%d: warning: ignoring %s keys %s\n", reader.file().c_str(), map.line(), where,
                     unknown.c_str());
}

// A transform list as balboa's parse_transformation reads it, applied in the order listed (M = T_n ... T_1).
// `lookat` takes {position, target, up} and places its object at `position` looking at `target` (eq. (28));
// rotate, scale and translate are raster's own transform steps.
std::vector<TransformStep> read_seed001_transform(const Node& list, const DocumentReader& reader) {
    reader.expect_sequence(list, "transform");
    std::vector<TransformStep> steps;
    for (const Node& step : list.items()) {
        const Node& lookat = step.is_map() && step.size() == 1 ? reader.optional(step, "lookat") : Node::undefined();
        if (!lookat.is_defined()) {
            steps.push_back(read_transform_steps({step}, reader).front());
            continue;
        }
        reader.expect_map(lookat, "lookat");
        reader.check_keys(lookat, {"position", "target", "up"});
        Camera frame;
        frame.eye = reader.vec3(reader.required(lookat, "position"), "lookat position");
        frame.target = reader.vec3(reader.required(lookat, "target"), "lookat target");
        if (const Node& up = reader.optional(lookat, "up"); up.is_defined()) frame.up = reader.vec3(up, "lookat up");
        if (const auto camera = camera_problem(frame)) {
            // camera_problem speaks of a camera's eye; balboa calls it the position.
            std::string problem = camera->message.substr(camera->message.find(' ') + 1);
            if (problem.rfind("eye", 0) == 0) problem.replace(0, 3, "position");
            reader.fail(lookat, "lookat: " + problem);
        }
        steps.push_back(LookAtStep{frame.eye, frame.target, frame.up});
    }
    return steps;
}

// Numbers in threes, written flat ([x0, y0, z0, x1, ...] as the document prints them) or as [[x, y, z], ...].
// `element` reads one number; the result holds one entry per triple.
template <typename Triple, typename ReadElement>
std::vector<Triple> read_triples(const Node& list, const DocumentReader& reader, const char* what,
                                 ReadElement read_element) {
    reader.expect_sequence(list, what);
    std::vector<Triple> triples;
    const bool nested = list.size() > 0 && list[0].is_sequence();
    if (nested) {
        for (const Node& entry : list.items()) {
            if (!entry.is_sequence() || entry.size() != 3) reader.fail(entry, std::string(what) + " entries are [a, b, c]");
            triples.push_back(Triple{read_element(entry[0]), read_element(entry[1]), read_element(entry[2])});
        }
        return triples;
    }
    if (list.size() % 3 != 0)
        reader.fail(list, std::string(what) + " must hold a multiple of 3 numbers, has " + std::to_string(list.size()));
    for (size_t i = 0; i < list.size(); i += 3)
        triples.push_back(Triple{read_element(list[i]), read_element(list[i + 1]), read_element(list[i + 2])});
    return triples;
}

std::vector<glm::vec3> read_vectors(const Node& list, const DocumentReader& reader, const char* what) {
    if (list.size() > 3 * kMaxMeshVertices) reader.fail(list, std::string("too many ") + what);
    return read_triples<glm::vec3>(list, reader, what, [&](const Node& n) { return reader.finite_float(n, what); });
}

MeshData read_inline_object(const Node& node, const DocumentReader& reader) {
    MeshData mesh;
    mesh.positions = read_vectors(reader.required(node, "vertices"), reader, "vertices");
    const int last = static_cast<int>(mesh.positions.size()) - 1;
    const Node& faces = reader.required(node, "faces");
    if (faces.size() > 3 * kMaxMeshTriangles) reader.fail(faces, "too many faces");
    mesh.triangles = read_triples<TriangleIndices>(faces, reader, "faces", [&](const Node& n) {
        return static_cast<uint32_t>(reader.integer(n, "a face index", 0, last));
    });
    if (const Node& colors = reader.optional(node, "vertex_colors"); colors.is_defined()) {
        mesh.colors = read_vectors(colors, reader, "vertex_colors");
        if (mesh.colors.size() != mesh.positions.size())
            reader.fail(colors, "vertex_colors must have one colour per vertex (" + std::to_string(mesh.positions.size()) +
                                    "), has " + std::to_string(mesh.colors.size()));
    }
    if (const Node& colors = reader.optional(node, "face_colors"); colors.is_defined()) {
        mesh.face_colors = read_vectors(colors, reader, "face_colors");
        if (mesh.face_colors.size() != mesh.triangles.size())
            reader.fail(colors, "face_colors must have one colour per face (" + std::to_string(mesh.triangles.size()) +
                                    "), has " + std::to_string(mesh.face_colors.size()));
    }
    mesh.object_names.push_back("inline");
    mesh.object_first_triangle.push_back(0);
    return mesh;
}

}  // namespace

void read_seed001_scene(const Node& root, const DocumentReader& reader, const MeshFileLoader& load_mesh, Scene& scene) {
    warn_unknown_keys(root, reader, {"camera", "background", "objects"}, "top-level");
    const Node& camera = reader.required(root, "camera");
    reader.expect_map(camera, "camera");
    warn_unknown_keys(camera, reader, {"resolution", "transform", "s", "z_near"}, "camera");

    RenderSettings& settings = scene.settings;
    settings.width = kSeed001DefaultWidth;
    settings.height = kSeed001DefaultHeight;
    if (const Node& resolution = reader.optional(camera, "resolution"); resolution.is_defined()) {
        if (!resolution.is_sequence() || resolution.size() != 2) reader.fail(resolution, "resolution is [width, height]");
        settings.width = reader.integer(resolution[0], "resolution width", 1, kMaxImageDimension);
        settings.height = reader.integer(resolution[1], "resolution height", 1, kMaxImageDimension);
    }
    float s = kSeed001DefaultS, z_near = kSeed001DefaultZNear;
    const Node &s_node = reader.optional(camera, "s"), &z_near_node = reader.optional(camera, "z_near");
    if (s_node.is_defined()) s = reader.finite_float(s_node, "camera s");
    if (z_near_node.is_defined()) z_near = reader.finite_float(z_near_node, "camera z_near");
    if (std::string problem = seed001_camera_problem(s, z_near); !problem.empty())
        reader.fail(problem.rfind("s ", 0) == 0 ? (s_node.is_defined() ? s_node : camera)
                                                : (z_near_node.is_defined() ? z_near_node : camera),
                    problem);
    set_seed001_camera(s, z_near, scene);
    if (std::string problem = settings_problem(settings); !problem.empty()) reader.fail(camera, problem);

    // The camera's transform is camera-to-world; its inverse, the view, follows every object's own steps (unlit
    // shading needs no world space), so raster's camera stays at the origin.
    std::vector<TransformStep> camera_to_world;
    if (const Node& transform = reader.optional(camera, "transform"); transform.is_defined()) {
        camera_to_world = read_seed001_transform(transform, reader);
        if (!(std::fabs(glm::determinant(compose_steps(camera_to_world))) > 1e-12f))
            reader.fail(transform, "the camera transform is not invertible");
    }

    settings.background = glm::vec3(kSeed001Background);
    if (const Node& background = reader.optional(root, "background"); background.is_defined())
        settings.background = reader.vec3(background, "background", true);

    const Node& objects = reader.required(root, "objects");
    reader.expect_sequence(objects, "objects");
    for (const Node& node : objects.items()) {
        reader.expect_map(node, "an object");
        warn_unknown_keys(node, reader, {"filename", "vertices", "faces", "vertex_colors", "face_colors", "transform"},
                          "object");
        SceneMesh mesh;
        const Node& filename = reader.optional(node, "filename");
        if (filename.is_defined() == reader.optional(node, "vertices").is_defined())
            reader.fail(node, "an object has either 'filename' (a PLY or OBJ file) or inline 'vertices' and 'faces'");
        if (filename.is_defined()) {
            mesh.source = reader.string(filename, "filename");
            mesh.data = load_mesh(filename, mesh.source);
        } else {
            mesh.source = reader.file() + ":" + std::to_string(node.line()) + " (inline object)";
            mesh.data = shared_mesh_data(read_inline_object(node, reader));
        }
        if (const Node& transform = reader.optional(node, "transform"); transform.is_defined())
            mesh.transform.steps = read_seed001_transform(transform, reader);
        mesh.transform.then_inverse_of = camera_to_world;
        scene.meshes.push_back(std::move(mesh));
    }
}

}  // namespace raster
