// The project's own scene format (YAML; docs/scene-format.md): every field optional except what a scene needs.
#include <cmath>

#include <glm/geometric.hpp>

#include "raster/scene/validation.h"
#include "raster/scene/sample_counts.h"
#include "raster/formats/scene_formats.h"
#include "raster/texture/texture.h"

namespace raster {

TransformStep read_transform_step(const std::string& kind, const Node& value, const DocumentReader& reader) {
    if (kind == "translate") return TranslateStep{reader.vec3(value, "translate")};
    if (kind == "scale") return ScaleStep{reader.vec3(value, "scale", true)};
    if (kind == "rotate") {
        // {angle: degrees, axis: [x, y, z]} or [degrees, x, y, z]
        RotateStep rotate;
        if (value.is_map()) {
            reader.check_keys(value, {"angle", "axis"});
            rotate.degrees = reader.finite_float(reader.required(value, "angle"), "rotate angle");
            rotate.axis = reader.vec3(reader.required(value, "axis"), "rotate axis");
        } else {
            if (!value.is_sequence() || value.size() != 4)
                reader.fail(value, "rotate is {angle: degrees, axis: [x, y, z]} or [degrees, x, y, z]");
            rotate.degrees = reader.finite_float(value[0], "rotate angle");
            rotate.axis = {reader.finite_float(value[1], "rotate axis"), reader.finite_float(value[2], "rotate axis"),
                           reader.finite_float(value[3], "rotate axis")};
        }
        if (!(glm::length(rotate.axis) > 0.0f)) reader.fail(value, "rotate axis must not be zero");
        return rotate;
    }
    if (kind == "quaternion") {
        if (!value.is_sequence() || value.size() != 4) reader.fail(value, "quaternion is [w, x, y, z]");
        QuaternionStep quaternion;
        for (int i = 0; i < 4; ++i) quaternion.wxyz[i] = reader.finite_float(value[i], "quaternion");
        if (!(glm::dot(quaternion.wxyz, quaternion.wxyz) > 0.0f)) reader.fail(value, "quaternion must not be zero");
        return quaternion;
    }
    // lookat: place the object at `eye`, facing `target` with its -z axis
    reader.expect_map(value, "lookat");
    reader.check_keys(value, {"eye", "target", "up"});
    Camera frame;
    frame.eye = reader.vec3(reader.required(value, "eye"), "lookat eye");
    frame.target = reader.vec3(reader.required(value, "target"), "lookat target");
    if (const Node& up = reader.optional(value, "up"); up.is_defined()) frame.up = reader.vec3(up, "lookat up");
    if (const auto problem = camera_problem(frame))
        reader.fail(value, "lookat: " + problem->message.substr(problem->message.find(' ') + 1));
    return LookAtStep{frame.eye, frame.target, frame.up};
}

std::vector<TransformStep> read_transform_steps(const std::vector<std::reference_wrapper<const Node>>& steps,
                                               const DocumentReader& reader) {
    std::vector<TransformStep> out;
    for (const Node& step : steps) {
        if (!step.is_map() || step.size() != 1)
            reader.fail(step, "each transform step is a map with one key: translate, rotate, quaternion, scale or lookat");
        reader.check_keys(step, {"translate", "rotate", "quaternion", "scale", "lookat"});
        out.push_back(read_transform_step(step.entries().front().key.text(), step.entries().front().value, reader));
    }
    return out;
}

std::vector<TransformStep> read_transform_chain(const Node& list, const DocumentReader& reader) {
    reader.expect_sequence(list, "transform");
    return read_transform_steps(list.items(), reader);
}

const Node& camera_node_to_blame(const CameraNodes& nodes, CameraField field) {
    auto first_defined = [&](const Node& value, const Node& relative_to) -> const Node& {
        return value.is_defined() ? value : relative_to.is_defined() ? relative_to : nodes.map;
    };
    switch (field) {
        case CameraField::eye: return first_defined(nodes.eye, nodes.map);
        case CameraField::target: return first_defined(nodes.target, nodes.eye);
        case CameraField::up: return first_defined(nodes.up, nodes.eye);
        case CameraField::fov: return first_defined(nodes.fov, nodes.map);
        case CameraField::near: return first_defined(nodes.near, nodes.map);
        case CameraField::far: return first_defined(nodes.far, nodes.near);
        case CameraField::ortho_height: return first_defined(nodes.height, nodes.map);
    }
    return nodes.map;
}

namespace {

glm::vec3 read_color(const Node& node, const DocumentReader& reader, const char* what) {
    return reader.vec3(node, what, true);
}

void read_image(const Node& node, const DocumentReader& reader, RenderSettings& settings) {
    reader.expect_map(node, "image");
    reader.check_keys(node, {"width", "height", "background"});
    if (const Node& v = reader.optional(node, "width"); v.is_defined())
        settings.width = reader.integer(v, "image width", 1, kMaxImageDimension);
    if (const Node& v = reader.optional(node, "height"); v.is_defined())
        settings.height = reader.integer(v, "image height", 1, kMaxImageDimension);
    if (const Node& v = reader.optional(node, "background"); v.is_defined())
        settings.background = read_color(v, reader, "background");
}

void read_camera(const Node& node, const DocumentReader& reader, Camera& camera) {
    reader.expect_map(node, "camera");
    reader.check_keys(node, {"eye", "target", "up", "fov", "near", "far", "projection", "height"});
    const Node &eye = reader.optional(node, "eye"), &target = reader.optional(node, "target"),
               &up = reader.optional(node, "up"), &fov = reader.optional(node, "fov"),
               &near = reader.optional(node, "near"), &far = reader.optional(node, "far"),
               &projection = reader.optional(node, "projection"), &height = reader.optional(node, "height");
    if (projection.is_defined()) {
        const std::string kind = reader.string(projection, "camera projection");
        if (kind == "orthographic") camera.projection = Projection::orthographic;
        else if (kind == "perspective") camera.projection = Projection::perspective;
        else reader.fail(projection, "camera projection must be perspective or orthographic, got '" + kind + "'");
    }
    const bool orthographic = camera.projection == Projection::orthographic;
    if (fov.is_defined() && orthographic) reader.fail(fov, "camera fov is for a perspective camera; an orthographic one takes height");
    if (height.is_defined() && !orthographic)
        reader.fail(height, "camera height is for an orthographic camera (projection: orthographic); a perspective one takes fov");
    if (eye.is_defined()) camera.eye = reader.vec3(eye, "camera eye");
    if (target.is_defined()) camera.target = reader.vec3(target, "camera target");
    if (up.is_defined()) camera.up = reader.vec3(up, "camera up");
    if (fov.is_defined()) camera.fov_y_degrees = reader.finite_float(fov, "camera fov");
    if (height.is_defined()) camera.ortho_height = reader.finite_float(height, "camera height");
    if (near.is_defined()) camera.near = reader.finite_float(near, "camera near");
    if (far.is_defined()) camera.far = reader.finite_float(far, "camera far");
    if (const auto problem = camera_problem(camera))
        reader.fail(camera_node_to_blame({node, eye, target, up, fov, near, far, height}, problem->field),
                    problem->message);
}

// The image size, sample count and frame memory together, once both sections are read, at the value to change.
void check_settings(const Node& root, const DocumentReader& reader, const RenderSettings& settings) {
    const std::string problem = settings_problem(settings);
    if (problem.empty()) return;
    const Node &image = reader.optional(root, "image"), &render = reader.optional(root, "render");
    const Node& samples = render.is_defined() ? reader.optional(render, "samples") : render;
    const Node& pattern = render.is_defined() ? reader.optional(render, "pattern") : render;
    if (!sample_count_error(settings.samples, settings.pattern).empty())
        reader.fail(samples.is_defined() ? samples : pattern.is_defined() ? pattern : root, problem);
    if (samples.is_defined() && settings.samples > 1) reader.fail(samples, problem);  // the multiplier of the frame
    reader.fail(image.is_defined() ? image : root, problem);
}

Light read_light(const Node& node, const DocumentReader& reader) {
    reader.expect_map(node, "a light");
    reader.check_keys(node, {"type", "position", "direction", "inner_cone", "outer_cone", "color", "intensity",
                             "attenuation", "shadows"});
    Light light;
    const Node& type = reader.optional(node, "type");
    if (type.is_defined()) {
        const std::string kind = reader.string(type, "light type");
        if (kind == "directional") light.type = LightType::directional;
        else if (kind == "spot") light.type = LightType::spot;
        else if (kind != "point") reader.fail(type, "light type must be point, directional or spot, got '" + kind + "'");
    }
    const Node &position = reader.optional(node, "position"), &direction = reader.optional(node, "direction");
    // What each type is placed by: a point light its position, a directional one its direction, a spot light both.
    if (light.type == LightType::directional && position.is_defined())
        reader.fail(position, "a directional light has a direction, not a position");
    if (light.type == LightType::point && direction.is_defined())
        reader.fail(direction, "a point light has a position, not a direction (type: spot or directional has one)");
    if (light.type != LightType::directional)
        light.position = reader.vec3(reader.required(node, "position"), "light position");
    if (light.type != LightType::point) light.direction = reader.vec3(reader.required(node, "direction"), "light direction");
    for (const char* key : {"inner_cone", "outer_cone"}) {
        const Node& v = reader.optional(node, key);
        if (!v.is_defined()) continue;
        if (light.type != LightType::spot) reader.fail(v, std::string(key) + " is a spot light's (type: spot)");
        const float radians = static_cast<float>(reader.number(v, key) * (M_PI / 180.0));  // degrees in the file
        (std::string(key) == "inner_cone" ? light.inner_cone : light.outer_cone) = radians;
    }
    if (const Node& v = reader.optional(node, "color"); v.is_defined()) light.color = read_color(v, reader, "light color");
    if (const Node& v = reader.optional(node, "intensity"); v.is_defined())
        light.intensity = reader.finite_float(v, "light intensity");
    if (const Node& v = reader.optional(node, "attenuation"); v.is_defined())
        light.attenuate = reader.boolean(v, "light attenuation");
    if (const Node& v = reader.optional(node, "shadows"); v.is_defined()) light.shadows = reader.boolean(v, "light shadows");
    if (const std::string problem = light_problem(light); !problem.empty()) reader.fail(node, problem);
    return light;
}

// A material's texture keys: texture (an image file), filter, wrap, max_anisotropy (docs/textures.md).
void read_texture_keys(const Node& node, const DocumentReader& reader, const TextureFileLoader& load_texture,
                       Material& material) {
    const Node& file = reader.optional(node, "texture");
    if (!file.is_defined()) {
        for (const char* key : {"filter", "wrap", "max_anisotropy"})
            if (const Node& v = reader.optional(node, key); v.is_defined())
                reader.fail(v, std::string(key) + " is a texture setting, but the material has no texture");
        return;
    }
    TextureBinding binding;
    binding.texture = load_texture(file, reader.string(file, "texture"));
    binding.path = binding.texture->path;
    if (const Node& v = reader.optional(node, "filter"); v.is_defined()) {
        if (!parse_texture_filter(reader.string(v, "filter"), binding.filter))
            reader.fail(v, "filter must be nearest, bilinear, trilinear or anisotropic");
    }
    if (const Node& v = reader.optional(node, "wrap"); v.is_defined()) {
        if (!parse_texture_wrap(reader.string(v, "wrap"), binding.wrap))
            reader.fail(v, "wrap must be repeat, clamp or mirror");
    }
    if (const Node& v = reader.optional(node, "max_anisotropy"); v.is_defined())
        binding.max_anisotropy = reader.integer(v, "max_anisotropy", 1, 64);
    material.texture = binding;
}

Material read_material(const Node& node, const DocumentReader& reader, const TextureFileLoader& load_texture) {
    reader.expect_map(node, "material");
    reader.check_keys(node, {"color", "ambient", "diffuse", "specular", "exponent", "opacity", "texture", "filter",
                             "wrap", "max_anisotropy"});
    Material material;
    if (const Node& v = reader.optional(node, "color"); v.is_defined()) material.color = read_color(v, reader, "material color");
    if (const Node& v = reader.optional(node, "ambient"); v.is_defined()) material.ambient = read_color(v, reader, "ambient");
    if (const Node& v = reader.optional(node, "diffuse"); v.is_defined()) material.diffuse = read_color(v, reader, "diffuse");
    if (const Node& v = reader.optional(node, "specular"); v.is_defined()) material.specular = read_color(v, reader, "specular");
    if (const Node& v = reader.optional(node, "exponent"); v.is_defined()) {
        material.exponent = reader.finite_float(v, "exponent");
        if (material.exponent < 0.0f) reader.fail(v, "exponent must be >= 0");
    }
    if (const Node& v = reader.optional(node, "opacity"); v.is_defined()) {
        material.opacity = reader.finite_float(v, "opacity");
        if (material.opacity < 0.0f || material.opacity > 1.0f) reader.fail(v, "opacity must be in [0, 1]");
    }
    read_texture_keys(node, reader, load_texture, material);
    return material;
}

// Inline geometry: vertices, faces (triangles or polygons, fan-triangulated) and optional per-vertex normals,
// vertex colours or face colours.
MeshData read_inline_mesh(const Node& node, const DocumentReader& reader) {
    MeshData mesh;
    const Node& vertices = reader.required(node, "vertices");
    reader.expect_sequence(vertices, "vertices");
    if (vertices.size() > kMaxMeshVertices) reader.fail(vertices, "too many vertices");
    for (const Node& v : vertices.items()) mesh.positions.push_back(reader.vec3(v, "a vertex"));
    const Node& faces = reader.required(node, "faces");
    reader.expect_sequence(faces, "faces");
    std::vector<size_t> face_first_triangle;
    for (const Node& face : faces.items()) {
        if (!face.is_sequence() || face.size() < 3 || face.size() > kMaxPolygonVertices)
            reader.fail(face, "a face is a list of 3 or more vertex indices");
        std::vector<uint32_t> corners;
        for (const Node& index : face.items())
            corners.push_back(static_cast<uint32_t>(
                reader.integer(index, "a face index", 0, static_cast<int>(mesh.positions.size()) - 1)));
        face_first_triangle.push_back(mesh.triangles.size());
        for (size_t k = 1; k + 1 < corners.size(); ++k) mesh.triangles.push_back({{corners[0], corners[k], corners[k + 1]}});
        if (mesh.triangles.size() > kMaxMeshTriangles) reader.fail(face, "too many triangles");
    }
    // Colours may be a single number for grey (docs/scene-format.md); normals may not.
    auto per_vertex = [&](const char* key, std::vector<glm::vec3>& out, bool grey_ok) {
        const Node& list = reader.optional(node, key);
        if (!list.is_defined()) return;
        reader.expect_sequence(list, key);
        if (list.size() != mesh.positions.size())
            reader.fail(list, std::string(key) + " must have one entry per vertex (" +
                                  std::to_string(mesh.positions.size()) + "), has " + std::to_string(list.size()));
        for (const Node& v : list.items()) out.push_back(reader.vec3(v, key, grey_ok));
    };
    per_vertex("normals", mesh.normals, false);
    per_vertex("vertex_colors", mesh.colors, true);
    if (const Node& list = reader.optional(node, "uvs"); list.is_defined()) {
        reader.expect_sequence(list, "uvs");
        if (list.size() != mesh.positions.size())
            reader.fail(list, "uvs must have one entry per vertex (" + std::to_string(mesh.positions.size()) +
                                  "), has " + std::to_string(list.size()));
        std::vector<glm::vec2> uvs;
        for (const Node& v : list.items()) {
            if (!v.is_sequence() || v.size() != 2) reader.fail(v, "a uv is [u, v]");
            uvs.emplace_back(reader.finite_float(v[0], "u"), reader.finite_float(v[1], "v"));
        }
        for (const TriangleIndices& t : mesh.triangles) mesh.corner_uvs.push_back({{uvs[t.v[0]], uvs[t.v[1]], uvs[t.v[2]]}});
    }
    if (const Node& list = reader.optional(node, "face_colors"); list.is_defined()) {
        reader.expect_sequence(list, "face_colors");
        if (list.size() != faces.size())
            reader.fail(list, "face_colors must have one entry per face (" + std::to_string(faces.size()) + "), has " +
                                  std::to_string(list.size()));
        for (size_t face = 0; face < faces.size(); ++face) {
            const glm::vec3 color = read_color(list[face], reader, "a face colour");
            const size_t end = face + 1 < faces.size() ? face_first_triangle[face + 1] : mesh.triangles.size();
            for (size_t t = face_first_triangle[face]; t < end; ++t) mesh.face_colors.push_back(color);
        }
    }
    mesh.object_names.push_back("inline");
    mesh.object_first_triangle.push_back(0);
    return mesh;
}

}  // namespace

SceneMesh read_raster_mesh(const Node& node, const DocumentReader& reader, const SceneFileLoaders& files) {
    reader.expect_map(node, "a mesh");
    reader.check_keys(node, {"file", "vertices", "faces", "normals", "vertex_colors", "face_colors", "uvs",
                             "transform", "material"});
    SceneMesh mesh;
    const Node& file = reader.optional(node, "file");
    if (file.is_defined() == reader.optional(node, "vertices").is_defined())
        reader.fail(node, "a mesh has either 'file' or inline 'vertices' and 'faces'");
    if (file.is_defined()) {
        mesh.source = reader.string(file, "file");
        mesh.data = files.mesh(file, mesh.source);
    } else {
        mesh.source = reader.file() + ":" + std::to_string(node.line()) + " (inline mesh)";
        mesh.data = shared_mesh_data(read_inline_mesh(node, reader));
    }
    if (const Node& v = reader.optional(node, "transform"); v.is_defined()) mesh.transform.steps = read_transform_chain(v, reader);
    // The scene's material, when it gives one, is every triangle's; else an OBJ's own materials apply.
    if (const Node& v = reader.optional(node, "material"); v.is_defined())
        mesh.material = read_material(v, reader, files.texture);
    else if (file.is_defined())
        files.obj_materials(file, mesh.source, mesh, std::nullopt);
    return mesh;
}

void read_raster_scene(const Node& root, const DocumentReader& reader, const SceneFileLoaders& files, Scene& scene) {
    reader.check_keys(root, {"image", "camera", "render", "lights", "meshes", "shapes", "nodes"});
    if (const Node& v = reader.optional(root, "image"); v.is_defined()) read_image(v, reader, scene.settings);
    if (const Node& v = reader.optional(root, "render"); v.is_defined()) read_raster_render(v, reader, scene.settings);
    check_settings(root, reader, scene.settings);
    if (const Node& v = reader.optional(root, "camera"); v.is_defined()) read_camera(v, reader, scene.camera);
    if (const Node& v = reader.optional(root, "lights"); v.is_defined()) {
        reader.expect_sequence(v, "lights");
        for (const Node& light : v.items()) scene.lights.push_back(read_light(light, reader));
    }
    const Node& meshes = reader.optional(root, "meshes");
    if (!meshes.is_defined() && !reader.optional(root, "nodes").is_defined() && !reader.optional(root, "shapes").is_defined())
        reader.fail(root, "a scene needs 'meshes', or 'shapes' placed by 'nodes'");
    if (meshes.is_defined()) {
        reader.expect_sequence(meshes, "meshes");
        for (const Node& mesh : meshes.items()) scene.meshes.push_back(read_raster_mesh(mesh, reader, files));
    }
    read_raster_graph(root, reader, files, scene);
}

}  // namespace raster
