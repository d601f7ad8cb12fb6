// The raster format's scene graph: `shapes` defined once by name, `nodes` that place them, many times, each node's
// transform applied after its shape's own and before its parent's (docs/scene-format.md#a-scene-graph).
#include <map>
#include <memory>
#include <utility>
#include <string>
#include <vector>

#include "raster/formats/scene_formats.h"
#include "raster/transform/scene_pose.h"

namespace raster {
namespace {

// Each placement copies its shape's vertices, so the graph may place this many triangles in all; and a graph made
// of aliases (a YAML node may be named twice) is walked at most this many nodes and this deep.
constexpr uint64_t kMaxPlacedTriangles = kMaxMeshTriangles;
constexpr uint64_t kMaxNodeVisits = uint64_t{1} << 16;
constexpr int kMaxNodeDepth = 256;
// An alias visited again reads its keyframes and copies its chain again: their totals are capped too.
constexpr uint64_t kMaxGraphKeys = uint64_t{1} << 22;
constexpr uint64_t kMaxPlacedSteps = uint64_t{1} << 22;

class GraphReader {
public:
    GraphReader(const DocumentReader& reader, const SceneFileLoaders& files, Scene& scene)
        : reader_(reader), files_(files), scene_(scene) {}

    void read_shapes(const Node& shapes) {
        reader_.expect_map(shapes, "shapes (a map of names to meshes)");
        for (const Node::Entry& entry : shapes.entries()) {
            const std::string name = reader_.string(entry.key, "a shape's name");
            if (!shapes_.emplace(name, read_raster_mesh(entry.value, reader_, files_)).second)
                reader_.fail(entry.key, "shape '" + name + "' is defined twice");
        }
    }

    // Places every node of the list under `parent` (its chain, applied after theirs; `parent_node` its node in the
    // animation, -1 for the roots).
    void place(const Node& list, const std::vector<TransformStep>& parent, int depth, int parent_node) {
        reader_.expect_sequence(list, depth == 0 ? "nodes" : "children");
        for (const Node& node : list.items()) place_node(node, parent, depth + 1, parent_node);
    }

    // The animation, when a node has keyframes: every node as it moves, every placement on its node.
    void finish_animation() {
        if (!animated_) return;
        animation_.meshes.resize(scene_.meshes.size());
        for (const auto& [mesh, placement] : placements_) animation_.meshes[mesh] = placement;
        find_animation_span(animation_);
        scene_.animation = std::make_shared<const SceneAnimation>(std::move(animation_));
    }

private:
    void place_node(const Node& node, const std::vector<TransformStep>& parent, int depth, int parent_node) {
        reader_.expect_map(node, "a node");
        if (depth > kMaxNodeDepth) reader_.fail(node, "nodes nest more than " + std::to_string(kMaxNodeDepth) + " deep");
        if (++visits_ > kMaxNodeVisits)
            reader_.fail(node, "the graph has more than " + std::to_string(kMaxNodeVisits) + " node placements");
        reader_.check_keys(node, {"name", "transform", "shape", "children", "keyframes", "interpolation"});
        std::vector<TransformStep> chain;
        if (const Node& v = reader_.optional(node, "transform"); v.is_defined()) chain = read_transform_chain(v, reader_);
        AnimatedNode animated;
        animated.parent = parent_node;
        animated.fixed = chain;
        if (const Node& keys = reader_.optional(node, "keyframes"); keys.is_defined()) {
            keys_ += keys.size();
            if (keys_ > kMaxGraphKeys)
                reader_.fail(keys, "the graph's nodes have more than " + std::to_string(kMaxGraphKeys) + " keyframes in all");
            read_raster_keyframes(node, reader_, animated);
            animated_ = true;
        } else if (const Node& v = reader_.optional(node, "interpolation"); v.is_defined()) {
            reader_.fail(v, "interpolation applies to keyframes; the node has none");
        }
        const int index = static_cast<int>(animation_.nodes.size());
        animation_.nodes.push_back(std::move(animated));
        chain.insert(chain.end(), parent.begin(), parent.end());
        if (const Node& v = reader_.optional(node, "shape"); v.is_defined()) place_shape(v, chain, index);
        if (const Node& v = reader_.optional(node, "children"); v.is_defined()) place(v, chain, depth, index);
    }

    void place_shape(const Node& name_node, const std::vector<TransformStep>& chain, int node) {
        const std::string name = reader_.string(name_node, "shape");
        const auto found = shapes_.find(name);
        if (found == shapes_.end()) {
            std::string known;
            for (const auto& [shape, unused] : shapes_) known += (known.empty() ? "" : ", ") + shape;
            reader_.fail(name_node, "no shape is named '" + name + "'" +
                                        (known.empty() ? std::string(" (the scene defines no shapes)") : " (shapes: " + known + ")"));
        }
        placed_triangles_ += found->second.data->triangles.size();
        placed_steps_ += found->second.transform.steps.size() + chain.size();
        if (placed_steps_ > kMaxPlacedSteps)
            reader_.fail(name_node, "the nodes' chains hold more than " + std::to_string(kMaxPlacedSteps) + " steps in all");
        if (placed_triangles_ > kMaxPlacedTriangles)
            reader_.fail(name_node, "the nodes place more than " + std::to_string(kMaxPlacedTriangles) + " triangles");
        SceneMesh mesh = found->second;
        placements_.emplace_back(scene_.meshes.size(), SceneAnimation::Placement{node, mesh.transform.steps});
        mesh.transform.steps.insert(mesh.transform.steps.end(), chain.begin(), chain.end());
        scene_.meshes.push_back(std::move(mesh));
    }

    const DocumentReader& reader_;
    const SceneFileLoaders& files_;
    Scene& scene_;
    std::map<std::string, SceneMesh> shapes_;
    SceneAnimation animation_;
    std::vector<std::pair<size_t, SceneAnimation::Placement>> placements_;  // scene mesh index, its placement
    bool animated_ = false;
    uint64_t placed_triangles_ = 0, visits_ = 0, keys_ = 0, placed_steps_ = 0;
};

}  // namespace

void read_raster_graph(const Node& root, const DocumentReader& reader, const SceneFileLoaders& files, Scene& scene) {
    GraphReader graph(reader, files, scene);
    const Node& shapes = reader.optional(root, "shapes");
    const Node& nodes = reader.optional(root, "nodes");
    if (shapes.is_defined()) graph.read_shapes(shapes);
    if (nodes.is_defined()) graph.place(nodes, {}, 0, -1);
    else if (shapes.is_defined()) reader.fail(shapes, "shapes are drawn only where 'nodes' place them; the scene has no nodes");
    graph.finish_animation();
    pose_scene(scene, 0.0f);  // an animated scene is drawn as its keys have it at time 0
}

}  // namespace raster
