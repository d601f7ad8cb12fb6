// The seed 003 course's JSON scene: eye / lookat / up / fov_angle / width / height / near / far, lights and
// meshes loaded from OBJ files with Blinn-Phong materials.
#include <cstdio>

#include "raster/scene/validation.h"
#include "raster/compat/seed_scene_readers.h"

namespace raster {

void read_seed003_scene(const Node& root, const DocumentReader& reader, const SceneFileLoaders& files, Scene& scene) {
    const auto known = {"eye", "lookat", "up", "fov_angle", "width", "height", "near", "far", "lights", "meshes"};
    if (std::string unknown = reader.unknown_keys(root, known); !unknown.empty())
        std::fprintf(stderr, "%s: warning: ignoring keys %s\n", reader.file().c_str(), unknown.c_str());

    RenderSettings& settings = scene.settings;
    settings.width = reader.integer(reader.required(root, "width"), "width", 1, kMaxImageDimension);
    settings.height = reader.integer(reader.required(root, "height"), "height", 1, kMaxImageDimension);
    settings.shading = ShadingMode::blinn_phong;  // the document's Phong shading: per-fragment Blinn-Phong

    Camera& camera = scene.camera;
    const Node &eye = reader.required(root, "eye"), &lookat = reader.required(root, "lookat"),
               &up = reader.required(root, "up"), &fov = reader.required(root, "fov_angle");
    camera.eye = reader.vec3(eye, "eye");
    camera.target = reader.vec3(lookat, "lookat");
    camera.up = reader.vec3(up, "up");
    camera.fov_y_degrees = reader.finite_float(fov, "fov_angle");
    const Node &near = reader.required(root, "near"), &far = reader.required(root, "far");
    camera.near = reader.finite_float(near, "near");
    camera.far = reader.finite_float(far, "far");
    // The document follows the textbook: near and far are z coordinates, both negative, with near > far.
    // Distances (both positive) are accepted too.
    if (camera.near < 0.0f && camera.far < 0.0f) {
        camera.near = -camera.near;
        camera.far = -camera.far;
    } else if ((camera.near < 0.0f) != (camera.far < 0.0f)) {
        reader.fail(near, "near and far must both be negative z values (the book's convention) or both distances");
    }
    if (const auto problem = camera_problem(camera))
        reader.fail(camera_node_to_blame({root, eye, lookat, up, fov, near, far, root}, problem->field), problem->message);

    if (const Node& lights = reader.optional(root, "lights"); lights.is_defined()) {
        reader.expect_sequence(lights, "lights");
        for (const Node& node : lights.items()) {
            reader.expect_map(node, "a light");
            Light light;
            light.position = reader.vec3(reader.required(node, "position"), "light position");
            light.color = reader.vec3(reader.required(node, "color"), "light color");
            // raster's extension (docs/seeds.md "Seed 003"): the document's shadow-map extra, per light.
            if (const Node& v = reader.optional(node, "shadows"); v.is_defined())
                light.shadows = reader.boolean(v, "light shadows");
            scene.lights.push_back(light);
        }
    }
    const Node& meshes = reader.required(root, "meshes");
    reader.expect_sequence(meshes, "meshes");
    for (const Node& node : meshes.items()) {
        reader.expect_map(node, "a mesh");
        SceneMesh mesh;
        const Node& obj = reader.required(node, "obj");
        mesh.source = reader.string(obj, "obj");
        mesh.data = files.mesh(obj, mesh.source);
        if (!mesh.data->normals.empty()) mutable_data(mesh).normals.clear();  // the document: vertex normals are the average of the adjacent face normals
        mesh.material.color = glm::vec3(1.0f);
        mesh.material.ambient = reader.vec3(reader.required(node, "ambient"), "ambient");
        mesh.material.diffuse = reader.vec3(reader.required(node, "diffuse"), "diffuse");
        mesh.material.specular = reader.vec3(reader.required(node, "specular"), "specular");
        mesh.material.exponent = reader.finite_float(reader.required(node, "phong_exponent"), "phong_exponent");
        // The scene sets the coefficients; the OBJ's materials (mtllib, usemtl) add their textures (map_Kd).
        files.obj_materials(obj, mesh.source, mesh, mesh.material);
        scene.meshes.push_back(std::move(mesh));
    }
}

}  // namespace raster
