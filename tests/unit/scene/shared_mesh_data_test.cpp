// Mesh data shared between placements: one copy for every placement of a mesh, and a change to one placement's
// data copies it first, so the others keep theirs.
#include "raster/scene/scene.h"

#include <gtest/gtest.h>

namespace raster {
namespace {

TEST(SharedMeshData, aPlacementsChangeCopiesSharedDataAndLeavesTheOthersAlone) {
    SceneMesh first;
    mutable_data(first).positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    SceneMesh second = first;  // a second placement of the same mesh
    ASSERT_EQ(first.data.get(), second.data.get());
    mutable_data(second).positions[0] = {5, 5, 5};
    EXPECT_NE(first.data.get(), second.data.get());
    EXPECT_EQ(first.data->positions[0], glm::vec3(0, 0, 0));
    EXPECT_EQ(second.data->positions[0], glm::vec3(5, 5, 5));
    EXPECT_EQ(second.data->positions[1], glm::vec3(1, 0, 0));  // the rest came with the copy
}

TEST(SharedMeshData, dataNoOtherPlacementHoldsChangesInPlace) {
    SceneMesh alone;
    const MeshData* before = alone.data.get();
    mutable_data(alone).positions.push_back({1, 2, 3});
    EXPECT_EQ(alone.data.get(), before);
    EXPECT_EQ(alone.data->positions.size(), 1u);
}

}  // namespace
}  // namespace raster
