// The raster format's scene graph: a shape placed by many nodes, each placement's chain its shape's steps, then its
// node's, then its parents' up to the root; an unknown shape, shapes without nodes and a graph that nests without
// end are clear errors.
#include <string>

#include <gtest/gtest.h>

#include "raster/compat/scene_loader.h"
#include "raster/core/errors.h"
#include "tests/support/placed_points.h"

namespace raster {
namespace {

using test_support::placed;

const std::string kShapes =
    "shapes:\n"
    "  tri:\n"
    "    vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0]]\n"
    "    faces: [[0, 1, 2]]\n"
    "    transform: [{translate: [0, 0, 1]}]\n";


std::string error_of(const std::string& text) {
    try {
        parse_scene(text, "scene.yaml");
    } catch (const InputError& e) {
        return std::to_string(e.line()) + ": " + e.message();
    }
    return "";
}

TEST(SceneGraph, aShapePlacedByTwoNodesIsDrawnWhereEachPutsIt) {
    const Scene scene = parse_scene(kShapes +
                                        "nodes:\n"
                                        "  - {shape: tri, transform: [{translate: [5, 0, 0]}]}\n"
                                        "  - {shape: tri, transform: [{scale: 2}]}\n",
                                    "scene.yaml");
    ASSERT_EQ(scene.meshes.size(), 2u);
    // The shape's own step first: (0, 0, 0) to (0, 0, 1); then the node's.
    EXPECT_EQ(placed(scene.meshes[0], {0, 0, 0}), glm::vec3(5, 0, 1));
    EXPECT_EQ(placed(scene.meshes[1], {0, 0, 0}), glm::vec3(0, 0, 2));
    EXPECT_EQ(scene.meshes[0].data.get(), scene.meshes[1].data.get());  // one copy of the vertices, shared
}

TEST(SceneGraph, aChildsChainIsItsOwnThenItsParents) {
    const Scene scene = parse_scene(kShapes +
                                        "nodes:\n"
                                        "  - transform: [{scale: 3}]\n"
                                        "    children:\n"
                                        "      - transform: [{translate: [1, 0, 0]}]\n"
                                        "        children: [{shape: tri}]\n",
                                    "scene.yaml");
    ASSERT_EQ(scene.meshes.size(), 1u);
    // (0, 0, 0): the shape's (0, 0, 1), the child's (1, 0, 1), the parent's (3, 0, 3).
    EXPECT_EQ(placed(scene.meshes[0], {0, 0, 0}), glm::vec3(3, 0, 3));
}

TEST(SceneGraph, meshesAndNodesTogether) {
    const Scene scene = parse_scene(kShapes +
                                        "meshes: [{vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0]], faces: [[0, 1, 2]]}]\n"
                                        "nodes: [{shape: tri}]\n",
                                    "scene.yaml");
    EXPECT_EQ(scene.meshes.size(), 2u);
}

TEST(SceneGraph, errorsNameTheLineAndTheProblem) {
    EXPECT_EQ(error_of(kShapes + "nodes: [{shape: tri2}]\n"), "6: no shape is named 'tri2' (shapes: tri)");
    EXPECT_EQ(error_of(kShapes), "2: shapes are drawn only where 'nodes' place them; the scene has no nodes");
    EXPECT_EQ(error_of("image: {width: 10}\n"), "1: a scene needs 'meshes', or 'shapes' placed by 'nodes'");
    EXPECT_NE(error_of(kShapes + "nodes: [{shape: tri, colour: 1}]\n").find("unknown key 'colour'"), std::string::npos);
    EXPECT_NE(error_of(kShapes + "  tri: {vertices: [[0, 0, 0]], faces: []}\nnodes: []\n").find("defined twice"),
              std::string::npos);
}

TEST(SceneGraph, aGraphOfAliasesIsBounded) {
    // Each node places the one before it twice: 2^30 placements of the triangle if nothing stopped it.
    std::string text = kShapes + "nodes:\n  - &n0 {shape: tri}\n";
    for (int i = 1; i <= 30; ++i)
        text += "  - &n" + std::to_string(i) + " {children: [*n" + std::to_string(i - 1) + ", *n" + std::to_string(i - 1) + "]}\n";
    EXPECT_NE(error_of(text).find("the graph has more than 65536 node placements"), std::string::npos) << error_of(text);
    // A node that is its own child nests without end.
    const std::string cycle = kShapes + "nodes:\n  - &a {shape: tri, children: [*a]}\n";
    EXPECT_NE(error_of(cycle).find("nodes nest more than 256 deep"), std::string::npos) << error_of(cycle);
}

}  // namespace
}  // namespace raster
