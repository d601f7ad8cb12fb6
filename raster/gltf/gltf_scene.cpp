// glTF 2.0 scenes read into raster's Scene (gltf_scene.h): the node trees walked, each mesh placed, the camera and
// lights found.
#include "raster/gltf/gltf_scene.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <map>
#include <memory>
#include <optional>

#include <glm/geometric.hpp>

#include "raster/core/errors.h"
#include "raster/core/file_io.h"
#include "raster/gltf/gltf_accessors.h"
#include "raster/gltf/gltf_animation.h"
#include "raster/gltf/gltf_material.h"
#include "raster/gltf/gltf_primitive.h"
#include "raster/gltf/gltf_warnings.h"
#include "raster/scene/validation.h"
#include "raster/transform/model_matrix.h"
#include "raster/transform/scene_bounds.h"
#include "raster/transform/scene_pose.h"

namespace raster {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kDefaultImageHeight = 480, kMaxImageSide = 16384;

// Extensions a file may require and still be drawn as its author meant.
bool understood(const std::string& extension) {
    return extension == "KHR_lights_punctual" || extension == "KHR_texture_transform";
}

using Steps = std::vector<TransformStep>;

// A node on the walk: its index, how deep it is, and its parent's chain (the root's last).
struct Pending {
    int node;
    int depth;
    std::shared_ptr<const Steps> parent_steps;
    int parent_animated;  // the parent's node in animation_.nodes, or -1 for a root
};

class ModelReader {
public:
    ModelReader(const tinygltf::Model& model, const std::string& file, Scene& scene, int camera)
        : model_(model), file_(file), warnings_(file), accessors_(model, file), materials_(model, file, warnings_),
          scene_(scene), wanted_camera_(camera) {}

    GltfSceneParts read();

private:
    [[noreturn]] void fail(const std::string& at, const std::string& message) const {
        throw InputError(file_, 0, 0, at + ": " + message);
    }
    float to_float(double value, const std::string& at) const {
        if (!std::isfinite(value) || std::fabs(value) > FLT_MAX) fail(at, "not a finite float: " + std::to_string(value));
        return static_cast<float>(value);
    }
    glm::vec3 vec3_of(const std::vector<double>& values, const std::string& at) const {
        if (values.size() != 3) fail(at, "needs 3 numbers, has " + std::to_string(values.size()));
        return {to_float(values[0], at), to_float(values[1], at), to_float(values[2], at)};
    }

    std::vector<int> root_nodes() const;
    Steps node_steps(const tinygltf::Node& node, const std::string& at) const;
    AnimatedNode animated_node(const Steps& own, int parent) const;
    void place_mesh(int mesh_index, const std::string& node_at, const Steps& steps);
    void place_camera(int camera_index, const std::string& node_at, const Steps& steps);
    void place_light(const tinygltf::Node& node, const std::string& node_at, const Steps& steps);
    // The camera's width over height sets the image's width; its height stays kDefaultImageHeight.
    void set_image_aspect(double ratio) {
        const double width = std::clamp(kDefaultImageHeight * ratio, 1.0, static_cast<double>(kMaxImageSide));
        scene_.settings.width = static_cast<int>(std::lround(width));
    }

    const tinygltf::Model& model_;
    std::string file_;
    GltfWarnings warnings_;
    GltfAccessorReader accessors_;
    GltfMaterials materials_;
    Scene& scene_;
    GltfSceneParts parts_;
    int wanted_camera_ = 0;  // which camera node the scene is drawn from, in walk order
    bool far_from_bounds_ = false;
    // Every node the walk reaches, as the animation would move it; kept only when the file has an animation.
    SceneAnimation animation_;
    std::vector<int> animated_index_;  // per glTF node: its node in animation_.nodes, or -1 when not reached
    int current_animated_ = -1;        // the node being placed
    uint64_t placed_triangles_ = 0, read_triangles_ = 0, placed_steps_ = 0;
    // Each primitive read once (null: not drawn) and placed many times, its data shared by the placements.
    std::map<std::pair<int, int>, std::shared_ptr<const MeshData>> primitives_;
};

std::vector<int> ModelReader::root_nodes() const {
    int scene = model_.defaultScene;
    if (scene >= 0 && static_cast<size_t>(scene) >= model_.scenes.size()) fail("/scene", "there is no scene " + std::to_string(scene));
    if (scene < 0 && !model_.scenes.empty()) scene = 0;
    if (scene >= 0) return model_.scenes[static_cast<size_t>(scene)].nodes;
    // No scenes: every node that is no node's child.
    std::vector<bool> child(model_.nodes.size(), false);
    for (const tinygltf::Node& node : model_.nodes)
        for (const int c : node.children)
            if (c >= 0 && static_cast<size_t>(c) < child.size()) child[static_cast<size_t>(c)] = true;
    std::vector<int> roots;
    for (size_t i = 0; i < child.size(); ++i)
        if (!child[i]) roots.push_back(static_cast<int>(i));
    return roots;
}

// The node's own transform as written, applied to the object first to last: its matrix, else scale, rotation and
// translation (M = T R S).
Steps ModelReader::node_steps(const tinygltf::Node& node, const std::string& at) const {
    Steps steps;
    if (!node.matrix.empty()) {
        if (node.matrix.size() != 16) fail(at + "/matrix", "needs 16 numbers, has " + std::to_string(node.matrix.size()));
        MatrixStep step;
        for (int i = 0; i < 16; ++i) step.matrix[i / 4][i % 4] = to_float(node.matrix[static_cast<size_t>(i)], at + "/matrix");
        steps.push_back(step);
        return steps;
    }
    if (!node.scale.empty()) steps.push_back(ScaleStep{vec3_of(node.scale, at + "/scale")});
    if (!node.rotation.empty()) {
        if (node.rotation.size() != 4) fail(at + "/rotation", "needs 4 numbers, has " + std::to_string(node.rotation.size()));
        glm::vec4 xyzw;  // as glTF writes it
        for (int i = 0; i < 4; ++i) xyzw[i] = to_float(node.rotation[static_cast<size_t>(i)], at + "/rotation");
        QuaternionStep step;
        step.wxyz = {xyzw.w, xyzw.x, xyzw.y, xyzw.z};
        if (step.wxyz == glm::vec4(0.0f)) fail(at + "/rotation", "the zero quaternion is no rotation");
        steps.push_back(step);
    }
    if (!node.translation.empty()) steps.push_back(TranslateStep{vec3_of(node.translation, at + "/translation")});
    return steps;
}

// The node at rest: a matrix node keeps its matrix as a fixed step (glTF animates only nodes without one); a TRS
// node's scale, rotation and translation are its rest values, which a channel replaces.
AnimatedNode ModelReader::animated_node(const Steps& own, int parent) const {
    AnimatedNode node;
    node.parent = parent;
    for (const TransformStep& step : own) {
        if (const auto* scale = std::get_if<ScaleStep>(&step)) node.rest_scale = scale->factors;
        else if (const auto* rotation = std::get_if<QuaternionStep>(&step)) node.rest_rotation = rotation->wxyz;
        else if (const auto* translation = std::get_if<TranslateStep>(&step)) node.rest_translation = translation->offset;
        else node.fixed.push_back(step);
    }
    return node;
}

void ModelReader::place_mesh(int mesh_index, const std::string& node_at, const Steps& steps) {
    if (static_cast<size_t>(mesh_index) >= model_.meshes.size()) fail(node_at + "/mesh", "there is no mesh " + std::to_string(mesh_index));
    const tinygltf::Mesh& mesh = model_.meshes[static_cast<size_t>(mesh_index)];
    for (size_t p = 0; p < mesh.primitives.size(); ++p) {
        const tinygltf::Primitive& primitive = mesh.primitives[p];
        const std::string at = "/meshes/" + std::to_string(mesh_index) + "/primitives/" + std::to_string(p);
        const GltfMaterial& material = materials_.at(primitive.material, at + "/material");
        if (material.cut_away) continue;  // never read: nothing of it is drawn
        auto [slot, fresh] = primitives_.try_emplace({mesh_index, static_cast<int>(p)});
        if (fresh) {
            if (std::optional<MeshData> read = read_gltf_primitive(accessors_, primitive, at, material, warnings_))
                slot->second = shared_mesh_data(std::move(*read));
            else
                warnings_.say(at + ": points and lines are not drawn");
            read_triangles_ += slot->second ? slot->second->triangles.size() : 0;
            if (read_triangles_ > kMaxGltfPlacedTriangles)
                fail(at, "the meshes hold more than " + std::to_string(kMaxGltfPlacedTriangles) + " triangles");
        }
        if (!slot->second) continue;
        placed_triangles_ += slot->second->triangles.size();
        placed_steps_ += steps.size();
        if (placed_triangles_ > kMaxGltfPlacedTriangles)
            fail(node_at + "/mesh", "the nodes place more than " + std::to_string(kMaxGltfPlacedTriangles) + " triangles");
        if (scene_.meshes.size() >= kMaxGltfPlacements || placed_steps_ > kMaxGltfPlacedSteps)
            fail(node_at + "/mesh", "the nodes place more than " + std::to_string(kMaxGltfPlacements) +
                                        " primitives, or chains of more than " + std::to_string(kMaxGltfPlacedSteps) +
                                        " steps in all");
        SceneMesh placed;
        placed.data = slot->second;
        placed.transform.steps = steps;
        placed.material = material.material;
        placed.source = file_ + "#" + at;
        scene_.meshes.push_back(std::move(placed));
        animation_.meshes.push_back({current_animated_, {}});
    }
}

void ModelReader::place_camera(int camera_index, const std::string& node_at, const Steps& steps) {
    if (static_cast<size_t>(camera_index) >= model_.cameras.size())
        fail(node_at + "/camera", "there is no camera " + std::to_string(camera_index));
    const tinygltf::Camera& camera = model_.cameras[static_cast<size_t>(camera_index)];
    const std::string at = "/cameras/" + std::to_string(camera_index);
    Camera& out = scene_.camera;
    if (camera.type == "orthographic") {
        const tinygltf::OrthographicCamera& o = camera.orthographic;
        if (!(o.xmag > 0.0)) fail(at + "/orthographic/xmag", "must be > 0, got " + std::to_string(o.xmag));
        if (!(o.ymag > 0.0)) fail(at + "/orthographic/ymag", "must be > 0, got " + std::to_string(o.ymag));
        if (!(o.znear >= 0.0)) fail(at + "/orthographic/znear", "must be >= 0, got " + std::to_string(o.znear));
        if (!(o.zfar > o.znear)) fail(at + "/orthographic/zfar", "must be > znear, got " + std::to_string(o.zfar));
        camera_from_pose(compose_steps(steps), out);
        animation_.camera_node = current_animated_;
        out.projection = Projection::orthographic;
        out.ortho_height = to_float(2.0 * o.ymag, at + "/orthographic/ymag");
        out.near = to_float(o.znear, at + "/orthographic/znear");
        out.far = to_float(o.zfar, at + "/orthographic/zfar");
        set_image_aspect(o.xmag / o.ymag);
        parts_.camera = true;
        return;
    }
    if (camera.type != "perspective") fail(at + "/type", "must be perspective or orthographic, got '" + camera.type + "'");
    const tinygltf::PerspectiveCamera& p = camera.perspective;
    if (!(p.yfov > 0.0 && p.yfov < kPi)) fail(at + "/perspective/yfov", "must be in (0, pi), got " + std::to_string(p.yfov));
    if (!(p.znear > 0.0)) fail(at + "/perspective/znear", "must be > 0, got " + std::to_string(p.znear));
    if (p.zfar != 0.0 && !(p.zfar > p.znear)) fail(at + "/perspective/zfar", "must be > znear, got " + std::to_string(p.zfar));
    camera_from_pose(compose_steps(steps), out);
    animation_.camera_node = current_animated_;
    out.fov_y_degrees = to_float(p.yfov * 180.0 / kPi, at + "/perspective/yfov");
    out.near = to_float(p.znear, at + "/perspective/znear");
    far_from_bounds_ = p.zfar == 0.0;  // an infinite projection: far is set to hold the scene once it is read
    if (!far_from_bounds_) out.far = to_float(p.zfar, at + "/perspective/zfar");
    if (p.aspectRatio > 0.0) set_image_aspect(p.aspectRatio);
    parts_.camera = true;
}

void ModelReader::place_light(const tinygltf::Node& node, const std::string& node_at, const Steps& steps) {
    const auto extension = node.extensions.find("KHR_lights_punctual");
    if (extension == node.extensions.end()) return;
    const tinygltf::Value& index = extension->second.Get("light");
    const std::string at = node_at + "/extensions/KHR_lights_punctual/light";
    if (!index.IsInt()) fail(at, "must be a light's index");
    const int light_index = index.GetNumberAsInt();
    if (light_index < 0 || static_cast<size_t>(light_index) >= model_.lights.size())
        fail(at, "there is no light " + std::to_string(light_index));
    const tinygltf::Light& light = model_.lights[static_cast<size_t>(light_index)];
    const std::string light_at = "/extensions/KHR_lights_punctual/lights/" + std::to_string(light_index);
    Light out;
    if (light.type == "directional") out.type = LightType::directional;
    else if (light.type == "spot") out.type = LightType::spot;
    else if (light.type != "point") fail(light_at + "/type", "must be point, directional or spot, got '" + light.type + "'");
    // At the node's origin, shining down its -z.
    const glm::mat4 pose = compose_steps(steps);
    out.position = glm::vec3(pose[3]);
    out.direction = -glm::vec3(pose[2]);
    if (out.type == LightType::spot) {
        out.inner_cone = to_float(light.spot.innerConeAngle, light_at + "/spot/innerConeAngle");
        out.outer_cone = to_float(light.spot.outerConeAngle, light_at + "/spot/outerConeAngle");
    }
    if (!light.color.empty()) out.color = vec3_of(light.color, light_at + "/color");
    out.intensity = to_float(light.intensity, light_at + "/intensity");
    if (out.intensity < 0.0f) fail(light_at + "/intensity", "must be >= 0");
    // Point and spot: candela, by the inverse square law; directional: lux, never attenuated.
    out.attenuate = out.type != LightType::directional;
    if (light.range > 0.0) warnings_.say(light_at + "/range: not read; the light reaches every distance");
    if (const std::string problem = light_problem(out); !problem.empty()) fail(light_at, problem);
    scene_.lights.push_back(out);
    animation_.light_nodes.push_back(current_animated_);
    parts_.lights = true;
}

GltfSceneParts ModelReader::read() {
    for (const std::string& extension : model_.extensionsRequired)
        if (!understood(extension)) fail("/extensionsRequired", "the file needs " + extension + ", which raster does not read");
    std::vector<Pending> stack;
    const std::vector<int> roots = root_nodes();
    const auto push_all = [&](const std::vector<int>& nodes, const std::string& at, int depth,
                              const std::shared_ptr<const Steps>& parent, int parent_animated) {
        for (size_t i = nodes.size(); i-- > 0;) {
            if (nodes[i] < 0 || static_cast<size_t>(nodes[i]) >= model_.nodes.size())
                fail(at + "/" + std::to_string(i), "there is no node " + std::to_string(nodes[i]));
            stack.push_back({nodes[i], depth, parent, parent_animated});
        }
    };
    push_all(roots, "/scenes/" + std::to_string(std::max(0, model_.defaultScene)) + "/nodes", 1, std::make_shared<const Steps>(), -1);
    animated_index_.assign(model_.nodes.size(), -1);  // a node with an index is one the walk has reached
    while (!stack.empty()) {
        const Pending pending = stack.back();
        stack.pop_back();
        const std::string at = "/nodes/" + std::to_string(pending.node);
        if (animated_index_[static_cast<size_t>(pending.node)] >= 0)
            fail(at, "is reached twice; glTF nodes form trees, each node with one parent and no cycles");
        if (pending.depth > kMaxGltfNodeDepth) fail(at, "is more than " + std::to_string(kMaxGltfNodeDepth) + " nodes deep");
        const tinygltf::Node& node = model_.nodes[static_cast<size_t>(pending.node)];
        auto steps = std::make_shared<Steps>(node_steps(node, at));
        current_animated_ = static_cast<int>(animation_.nodes.size());
        animated_index_[static_cast<size_t>(pending.node)] = current_animated_;
        animation_.nodes.push_back(animated_node(*steps, pending.parent_animated));
        steps->insert(steps->end(), pending.parent_steps->begin(), pending.parent_steps->end());
        if (node.skin >= 0) warnings_.say(at + ": skins are not applied; the mesh is drawn in its bind pose");
        if (node.mesh >= 0) place_mesh(node.mesh, at, *steps);
        if (node.camera >= 0) {
            if (static_cast<int>(parts_.cameras.size()) == wanted_camera_) place_camera(node.camera, at, *steps);
            parts_.cameras.push_back(node.name.empty() ? "camera " + std::to_string(parts_.cameras.size()) : node.name);
        }
        place_light(node, at, *steps);
        push_all(node.children, at + "/children", pending.depth + 1, steps, current_animated_);
    }
    if (placed_triangles_ == 0) fail("/scenes", "the scene places no triangles to draw");
    if (wanted_camera_ != 0 && wanted_camera_ >= static_cast<int>(parts_.cameras.size())) {
        std::string list;
        for (size_t i = 0; i < parts_.cameras.size(); ++i)
            list += (i ? ", " : "") + std::to_string(i) + " '" + parts_.cameras[i] + "'";
        fail("/nodes", "there is no camera " + std::to_string(wanted_camera_) + " to draw from; the scene places " +
                           std::to_string(parts_.cameras.size()) + (parts_.cameras.size() == 1 ? " camera" : " cameras") +
                           (list.empty() ? "" : ": " + list));
    }
    if (read_gltf_animation(model_, accessors_, animated_index_, animation_, warnings_)) {
        // Drawn as the animation has it at time 0 (--time poses another instant).
        find_animation_span(animation_);
        scene_.animation = std::make_shared<const SceneAnimation>(std::move(animation_));
    }
    if (far_from_bounds_) {
        // The reach of the scene from the eye, at 17 instants across an animation (the scene as drawn otherwise).
        double reach = 0.0;
        const SceneAnimation* animation = scene_.animation.get();
        const int instants = animation ? 17 : 1;
        for (int i = 0; i < instants; ++i) {
            if (animation) pose_scene(scene_, animation->start + (animation->end - animation->start) * static_cast<float>(i) / 16.0f);
            const WorldBounds bounds = *world_bounds(scene_);
            reach = std::max(reach, 1.1 * (glm::length(bounds.centre - glm::dvec3(scene_.camera.eye)) + bounds.radius));
        }
        scene_.camera.far = static_cast<float>(std::max(reach, 2.0 * scene_.camera.near));
    }
    pose_scene(scene_, 0.0f);  // an animated scene is drawn as its keys have it at time 0; a static one is left as is
    return parts_;
}

}  // namespace

bool is_gltf_file(const std::filesystem::path& path) {
    const std::string extension = lowercase_extension(path);
    return extension == ".gltf" || extension == ".glb";
}

GltfSceneParts read_gltf_scene(std::string_view bytes, const std::string& name, const GltfFileReader& files, Scene& scene,
                               int camera) {
    const tinygltf::Model model = parse_gltf_model(bytes, name, files);
    scene.path = name;
    return ModelReader(model, name, scene, camera).read();
}

}  // namespace raster
