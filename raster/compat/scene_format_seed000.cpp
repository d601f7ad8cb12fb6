// Seed 000 YAML configs: reads the five tasks' keys, builds the document's matrices, and turns a config into the
// raster scene its task renders.
#include "raster/compat/scene_format_seed000.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <sstream>

#include <glm/geometric.hpp>

#include "raster/core/errors.h"
#include "raster/core/file_io.h"
#include "raster/scene/validation.h"
#include "raster/scene/sample_counts.h"
#include "raster/transform/transform.h"

namespace raster {

const char* to_string(Seed000Task task) {
    switch (task) {
        case Seed000Task::triangle: return "triangle";
        case Seed000Task::transform: return "transform";
        case Seed000Task::transform_test: return "transform-test";
        case Seed000Task::shading_depth: return "shading-depth";
        case Seed000Task::shading: return "shading";
    }
    return "?";
}

namespace {

constexpr Seed000Task kTasks[] = {Seed000Task::triangle, Seed000Task::transform, Seed000Task::transform_test,
                                  Seed000Task::shading_depth, Seed000Task::shading};

bool is_shading_task(Seed000Task task) { return task == Seed000Task::shading || task == Seed000Task::shading_depth; }

std::string lowercase(std::string text) {
    for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return text;
}

// The document omits suffixes ("obj: trig" is trig.obj); a name that already carries one keeps it.
std::string with_suffix(const std::string& name, const char* suffix, std::initializer_list<const char*> kept) {
    const std::string lowered = lowercase(name);
    for (const char* ending : kept) {
        const std::string e(ending);
        if (lowered.size() > e.size() && lowered.compare(lowered.size() - e.size(), e.size(), e) == 0) return name;
    }
    return name + suffix;
}

// A colour or ambient term in the document's 0..255 scale.
glm::vec3 color_255(const Node& node, const DocumentReader& reader, const char* what) {
    const glm::vec3 color = reader.vec3(node, what, true);
    for (int i = 0; i < 3; ++i)
        if (color[i] < 0.0f || color[i] > 255.0f) reader.fail(node, std::string(what) + " components must be in 0..255");
    return color;
}

float non_negative(const Node& node, const DocumentReader& reader, const char* what) {
    const float value = reader.finite_float(node, what);
    if (value < 0.0f) reader.fail(node, std::string(what) + " must be >= 0");
    return value;
}

float positive(const Node& node, const DocumentReader& reader, const char* what) {
    const float value = reader.finite_float(node, what);
    if (!(value > 0.0f)) reader.fail(node, std::string(what) + " must be > 0");
    return value;
}

Seed000Task read_task(const Node& node, const DocumentReader& reader) {
    const std::string name = reader.string(node, "task");
    for (Seed000Task task : kTasks)
        if (name == to_string(task)) return task;
    reader.fail(node, "task must be triangle, transform, transform-test, shading-depth or shading, got '" + name + "'");
}

// `antialias` (none | SSAA) and `samples`. Only the triangle and transform tasks anti-alias; the shading tasks
// discard both, as the document says.
int read_samples(const Node& root, const DocumentReader& reader, Seed000Task task) {
    const Node &antialias = reader.optional(root, "antialias"), &samples = reader.optional(root, "samples");
    bool ssaa = false;
    if (antialias.is_defined()) {
        const std::string mode = lowercase(reader.string(antialias, "antialias"));
        if (mode != "none" && mode != "ssaa") reader.fail(antialias, "antialias must be 'none' or 'SSAA'");
        ssaa = mode == "ssaa";
    }
    const int count = samples.is_defined() ? reader.integer(samples, "samples", 1, kMaxGridSide * kMaxGridSide) : 1;
    if (is_shading_task(task) || !ssaa) return 1;
    if (!samples.is_defined()) reader.fail(antialias, "antialias: SSAA needs 'samples' (a positive integer)");
    const int side = static_cast<int>(std::lround(std::sqrt(count)));
    if (side * side != count && count != 2 && count != 8)
        reader.fail(samples, "samples must be a square (an N x N grid: 1, 4, 9, 16, ...) or 2 or 8, got " +
                                 std::to_string(count));
    return count;
}

Seed000Camera read_camera(const Node& node, const DocumentReader& reader) {
    reader.expect_map(node, "camera");
    reader.check_keys(node, {"pos", "lookAt", "up", "width", "height", "nearClip", "farClip"});
    Seed000Camera camera;
    camera.pos = reader.vec3(reader.required(node, "pos"), "camera pos");
    const Node& look_at = reader.required(node, "lookAt");
    camera.look_at = reader.vec3(look_at, "camera lookAt");
    const Node& up = reader.required(node, "up");
    camera.up = reader.vec3(up, "camera up");
    camera.width = positive(reader.required(node, "width"), reader, "camera width");
    camera.height = positive(reader.required(node, "height"), reader, "camera height");
    camera.near_clip = positive(reader.required(node, "nearClip"), reader, "camera nearClip");
    const Node& far = reader.required(node, "farClip");
    camera.far_clip = reader.finite_float(far, "camera farClip");
    if (!(camera.far_clip > camera.near_clip)) reader.fail(far, "camera farClip must be greater than nearClip");
    const glm::vec3 gaze = camera.look_at - camera.pos;
    if (!(glm::length(gaze) > 0.0f)) reader.fail(look_at, "camera lookAt is the camera's own position");
    if (!(glm::length(glm::cross(glm::normalize(gaze), camera.up)) > 1e-6f * glm::length(camera.up)))
        reader.fail(up, "camera up is parallel to the view direction (or zero)");
    return camera;
}

Seed000Transform read_transform(const Node& node, const DocumentReader& reader) {
    reader.expect_map(node, "a transform");
    reader.check_keys(node, {"rotation", "translation", "scale"});
    Seed000Transform transform;
    if (const Node& rotation = reader.optional(node, "rotation"); rotation.is_defined()) {
        if (!rotation.is_sequence() || rotation.size() != 4) reader.fail(rotation, "rotation is a quaternion [w, x, y, z]");
        for (int i = 0; i < 4; ++i) transform.rotation_wxyz[i] = reader.finite_float(rotation[i], "rotation");
        if (!(glm::length(transform.rotation_wxyz) > 0.0f)) reader.fail(rotation, "rotation must not be zero");
    }
    if (const Node& v = reader.optional(node, "translation"); v.is_defined())
        transform.translation = reader.vec3(v, "translation");
    if (const Node& v = reader.optional(node, "scale"); v.is_defined()) transform.scale = reader.vec3(v, "scale", true);
    return transform;
}

Seed000Light read_light(const Node& node, const DocumentReader& reader) {
    reader.expect_map(node, "a light");
    reader.check_keys(node, {"pos", "intensity", "color", "shadows"});
    Seed000Light light;
    light.pos = reader.vec3(reader.required(node, "pos"), "light pos");
    light.intensity = non_negative(reader.required(node, "intensity"), reader, "light intensity");
    light.color_255 = color_255(reader.required(node, "color"), reader, "light color");
    if (const Node& v = reader.optional(node, "shadows"); v.is_defined()) light.shadows = reader.boolean(v, "light shadows");
    return light;
}

}  // namespace

Seed000Config read_seed000_config(const Node& root, const DocumentReader& reader) {
    reader.check_keys(root, {"task", "antialias", "samples", "resolution", "obj", "output", "camera", "transforms",
                             "input", "expected", "exponent", "ambient", "lights"});
    Seed000Config config;
    config.task = read_task(reader.required(root, "task"), reader);
    const std::filesystem::path folder = std::filesystem::path(reader.file()).parent_path();

    const Node& resolution = reader.required(root, "resolution");
    reader.expect_map(resolution, "resolution");
    reader.check_keys(resolution, {"width", "height"});
    config.width = reader.integer(reader.required(resolution, "width"), "resolution width", 1, kMaxImageDimension);
    config.height = reader.integer(reader.required(resolution, "height"), "resolution height", 1, kMaxImageDimension);
    config.samples = read_samples(root, reader, config.task);

    const Node& obj = config.task == Seed000Task::transform_test ? reader.optional(root, "obj")
                                                                  : reader.required(root, "obj");
    if (obj.is_defined()) config.obj = with_suffix(reader.string(obj, "obj"), ".obj", {".obj"});
    std::string output = "output";
    if (const Node& v = reader.optional(root, "output"); v.is_defined()) output = reader.string(v, "output");
    config.output = folder / with_suffix(output, ".png", {".png", ".ppm"});

    if (config.task != Seed000Task::triangle) config.camera = read_camera(reader.required(root, "camera"), reader);
    if (const Node& list = reader.optional(root, "transforms"); list.is_defined()) {
        reader.expect_sequence(list, "transforms");
        for (const Node& entry : list.items()) config.transforms.push_back(read_transform(entry, reader));
    }
    if (config.task == Seed000Task::shading) {
        config.exponent = non_negative(reader.required(root, "exponent"), reader, "exponent");
        config.ambient_255 = color_255(reader.required(root, "ambient"), reader, "ambient");
        const Node& lights = reader.required(root, "lights");
        reader.expect_sequence(lights, "lights");
        for (const Node& light : lights.items()) config.lights.push_back(read_light(light, reader));
    }
    if (config.task == Seed000Task::transform_test) {
        config.input = glm::dvec3(reader.vec3(reader.required(root, "input"), "input"));
        const Node& expected = reader.required(root, "expected");
        if (!expected.is_sequence() || expected.size() != 4) reader.fail(expected, "expected is [x, y, z, w]");
        for (int i = 0; i < 4; ++i) config.expected[i] = reader.number(expected[i], "expected");
    }
    return config;
}

Seed000Config load_seed000_config(const std::filesystem::path& path) {
    const std::string name = path.string();
    const Document document = parse_document(read_file_bytes(path, kMaxSceneFileBytes), name);
    const Node& root = document.root();
    const DocumentReader reader(name);
    if (!root.is_map()) throw InputError(name, 1, 1, "a seed 000 config is a map of keys to values");
    return read_seed000_config(root, reader);
}

// ---- The document's matrices ----

glm::dmat4 seed000_model_matrix(const Seed000Transform& t) {
    const glm::vec4& q = t.rotation_wxyz;
    return glm::dmat4(translate_matrix(t.translation)) * glm::dmat4(quaternion_matrix(q[0], q[1], q[2], q[3])) *
           glm::dmat4(scale_matrix(t.scale));
}

glm::dmat4 seed000_view_matrix(const Seed000Camera& camera) {
    return glm::dmat4(look_at_matrix(camera.pos, camera.look_at, camera.up));
}

glm::dmat4 seed000_projection_matrix(const Seed000Camera& camera) {
    // Section 2.2.3 with the planes where a camera looking down -z has them: n = -nearClip, f = -farClip.
    const double n = -double(camera.near_clip), f = -double(camera.far_clip);
    glm::dmat4 perspective(0.0);  // m[column][row]
    perspective[0][0] = n;
    perspective[1][1] = n;
    perspective[2][2] = n + f;   // a3, from a3 + a4 / n = n and a3 + a4 / f = f
    perspective[3][2] = -n * f;  // a4
    perspective[2][3] = 1.0;
    // Orthographic: the box [l, r] x [b, t] x [f, n] to [-1, 1]^3, with l = -width/2, r = width/2 and so on.
    glm::dmat4 orthographic(1.0);
    orthographic[0][0] = 2.0 / double(camera.width);
    orthographic[1][1] = 2.0 / double(camera.height);
    orthographic[2][2] = 2.0 / (n - f);
    orthographic[3][2] = -(n + f) / (n - f);
    return orthographic * perspective;
}

glm::dmat4 seed000_screen_matrix(int width, int height) {
    glm::dmat4 m(1.0);
    m[0][0] = 0.5 * width;
    m[3][0] = 0.5 * width;
    m[1][1] = 0.5 * height;
    m[3][1] = 0.5 * height;
    return m;
}

Seed000TestResult run_seed000_transform_test(const Seed000Config& config) {
    Seed000TestResult result;
    result.expected = config.expected;
    if (!config.camera) return result;
    const glm::dmat4 model = config.transforms.empty() ? glm::dmat4(1.0) : seed000_model_matrix(config.transforms[0]);
    const glm::dmat4 full = seed000_screen_matrix(config.width, config.height) *
                            seed000_projection_matrix(*config.camera) * seed000_view_matrix(*config.camera) * model;
    const glm::dvec4 clip = full * glm::dvec4(config.input, 1.0);
    result.transformed = clip / clip.w;
    result.match = std::isfinite(result.transformed.x);
    for (int i = 0; i < 4; ++i)
        result.match = result.match && std::fabs(result.transformed[i] - result.expected[i]) <=
                                           kSeed000TestAbsoluteTolerance +
                                               kSeed000TestRelativeTolerance * std::fabs(result.expected[i]);
    return result;
}

std::string format_seed000_test_result(const Seed000TestResult& result) {
    std::ostringstream text;
    text << std::setprecision(7);
    auto row = [&](const char* label, const glm::dvec4& v) {
        text << label << v.x << ' ' << v.y << ' ' << v.z << ' ' << v.w << '\n';
    };
    row("transformed: ", result.transformed);
    row("expected:    ", result.expected);
    text << (result.match ? "match" : "MISMATCH") << " (tolerance per component: " << kSeed000TestAbsoluteTolerance
         << " + " << kSeed000TestRelativeTolerance << " * |expected|)\n";
    return text.str();
}

// ---- The scene a task renders ----

namespace {

// Object `index` of an OBJ as a mesh of its own: its triangles and only the vertices they use.
MeshData object_mesh(const MeshData& mesh, size_t index) {
    const size_t begin = mesh.object_first_triangle.empty() ? 0 : mesh.object_first_triangle[index];
    const size_t end = index + 1 < mesh.object_first_triangle.size() ? mesh.object_first_triangle[index + 1]
                                                                     : mesh.triangles.size();
    constexpr uint32_t kUnused = 0xFFFFFFFFu;
    MeshData object;
    std::vector<uint32_t> remap(mesh.positions.size(), kUnused);
    for (size_t t = begin; t < end; ++t) {
        TriangleIndices triangle = mesh.triangles[t];
        for (uint32_t& v : triangle.v) {
            if (remap[v] == kUnused) {
                remap[v] = static_cast<uint32_t>(object.positions.size());
                object.positions.push_back(mesh.positions[v]);
                if (!mesh.normals.empty()) object.normals.push_back(mesh.normals[v]);
            }
            v = remap[v];
        }
        object.triangles.push_back(triangle);
    }
    object.object_names.push_back(index < mesh.object_names.size() ? mesh.object_names[index] : "");
    object.object_first_triangle.push_back(0);
    return object;
}

// raster's camera for the document's: the vertical field of view that puts the near-plane rectangle's top and
// bottom edges at the image's top and bottom.
Camera raster_camera(const Seed000Camera& c) {
    Camera camera;
    camera.eye = c.pos;
    camera.target = c.look_at;
    camera.up = c.up;
    camera.fov_y_degrees = float(2.0 * std::atan(0.5 * double(c.height) / double(c.near_clip)) * (180.0 / M_PI));
    camera.near = c.near_clip;
    camera.far = c.far_clip;
    return camera;
}

// Eq. (1) through raster's pipeline: a camera at the origin with a 90 degree field of view, and a model matrix
// that puts OBJ point (x, y) at view (aspect * x, y, -1), which projects to NDC (x, y). raster's viewport then
// gives screen y = h/2 (1 - y), which is the document's canvas y' = h/2 (1 + y) counted from the top row.
void set_canvas_transform(int width, int height, Scene& scene, ModelTransform& transform) {
    scene.camera = Camera{};
    scene.camera.eye = glm::vec3(0.0f);
    scene.camera.target = glm::vec3(0.0f, 0.0f, -1.0f);
    scene.camera.fov_y_degrees = 90.0f;
    scene.camera.near = 0.5f;
    scene.camera.far = 2.0f;
    MatrixStep canvas;
    canvas.matrix[0][0] = static_cast<float>(width) / static_cast<float>(height);
    canvas.matrix[2][2] = 0.0f;  // eq. (1) drops z
    canvas.matrix[3][2] = -1.0f;
    transform.steps = {canvas};
}

}  // namespace

void read_seed000_scene(const Node& root, const DocumentReader& reader, const Seed000Config& config,
                        const MeshFileLoader& load_mesh, Scene& scene) {
    RenderSettings& settings = scene.settings;
    settings.width = config.width;
    settings.height = config.height;
    settings.background = glm::vec3(0.0f);
    settings.samples = config.samples;
    const int side = static_cast<int>(std::lround(std::sqrt(config.samples)));
    settings.pattern = side * side == config.samples ? SamplePattern::grid : SamplePattern::standard;
    settings.shading = config.task == Seed000Task::shading ? ShadingMode::blinn_phong : ShadingMode::unlit;
    settings.ambient_light = glm::vec3(1.0f);
    if (config.camera) {
        scene.camera = raster_camera(*config.camera);
        // raster's projection takes its aspect from the image, the document's from the camera rectangle.
        const double image_aspect = double(config.width) / config.height;
        const double camera_aspect = double(config.camera->width) / config.camera->height;
        if (config.task != Seed000Task::transform_test && std::fabs(camera_aspect / image_aspect - 1.0) > 1e-4)
            reader.fail(reader.required(reader.required(root, "camera"), "width"),
                        "camera width / height (" + std::to_string(camera_aspect) +
                            ") must equal resolution width / height (" + std::to_string(image_aspect) +
                            "): raster does not stretch the image");
        if (const auto problem = camera_problem(scene.camera))
            reader.fail(reader.required(root, "camera"), problem->message);
    }
    if (config.task == Seed000Task::transform_test || config.obj.empty()) return;  // nothing to draw

    const Node& obj_node = reader.required(root, "obj");
    const std::shared_ptr<const MeshData> loaded = load_mesh(obj_node, config.obj.string());
    const MeshData& mesh = *loaded;
    Material material;  // the document's objects are white: colour 1, lit only by `ambient` and the lights
    material.color = glm::vec3(1.0f);
    if (config.task == Seed000Task::shading) {
        material.ambient = config.ambient_255 / 255.0f;
        material.diffuse = glm::vec3(1.0f);
        material.specular = glm::vec3(1.0f);
        material.exponent = config.exponent;
        for (const Seed000Light& l : config.lights) {
            Light light;
            light.position = l.pos;
            light.color = l.color_255 / 255.0f;
            light.intensity = l.intensity;
            light.attenuate = true;  // 1 / r^2
            light.shadows = l.shadows;
            scene.lights.push_back(light);
        }
    }
    if (config.task == Seed000Task::triangle) {
        SceneMesh whole;
        MeshData uncoloured = mesh;
        uncoloured.colors.clear();
        uncoloured.face_colors.clear();
        whole.data = shared_mesh_data(std::move(uncoloured));
        whole.source = config.obj.string();
        whole.material = material;
        set_canvas_transform(config.width, config.height, scene, whole.transform);
        scene.meshes.push_back(std::move(whole));
        return;
    }
    const size_t objects = std::max<size_t>(1, mesh.object_first_triangle.size());
    if (objects != config.transforms.size())
        std::fprintf(stderr,
                     "%s: warning: %s has %zu object(s) but 'transforms' has %zu entr%s; objects without one are "
                     "drawn untransformed and extra entries are ignored\n",
                     reader.file().c_str(), config.obj.string().c_str(), objects, config.transforms.size(),
                     config.transforms.size() == 1 ? "y" : "ies");
    for (size_t k = 0; k < objects; ++k) {
        SceneMesh object;
        object.data = shared_mesh_data(object_mesh(mesh, k));
        object.source = config.obj.string() + " object " + std::to_string(k);
        object.material = material;
        if (k < config.transforms.size()) {
            // M = T R S: scale first, then the rotation, then the translation.
            const Seed000Transform& t = config.transforms[k];
            object.transform.steps = {ScaleStep{t.scale}, QuaternionStep{t.rotation_wxyz}, TranslateStep{t.translation}};
        }
        scene.meshes.push_back(std::move(object));
    }
}

}  // namespace raster
