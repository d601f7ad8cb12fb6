// glTF accessors: every count, offset, stride and index checked against the bytes there are, each refusal naming
// the JSON path of its problem; normalized integers read as the spec maps them; an accessor without a view is zeros.
#include "raster/gltf/gltf_accessors.h"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "tests/support/gltf_builder.h"

namespace raster {
namespace {

using test_support::GltfBuilder;
using test_support::read_built;
using test_support::read_error;

// A triangle whose POSITION accessor is the only one; tests spoil one field of it.
GltfBuilder triangle() { return GltfBuilder::one_triangle(); }

bool names(const std::string& message, const std::string& part) {
    return message.find(part) != std::string::npos;
}

TEST(GltfAccessors, aCountPastItsViewIsRefusedAtTheCount) {
    GltfBuilder b = triangle();
    b.document["accessors"][0]["count"] = 4;  // 48 bytes from a 36-byte view
    EXPECT_TRUE(names(read_error(b), "/accessors/0/count: 4 elements from byte 0 run past the buffer view's 36 bytes"))
        << read_error(b);
    b.document["accessors"][0]["count"] = 3;
    b.document["accessors"][0]["byteOffset"] = 4;
    EXPECT_TRUE(names(read_error(b), "/accessors/0/count")) << read_error(b);
}

TEST(GltfAccessors, aViewPastItsBufferIsRefusedAtItsLength) {
    GltfBuilder b = triangle();
    b.document["bufferViews"][0]["byteLength"] = 40;
    EXPECT_TRUE(names(read_error(b), "/bufferViews/0/byteLength")) << read_error(b);
    b.document["bufferViews"][0]["byteLength"] = 36;
    b.document["bufferViews"][0]["byteOffset"] = 4;
    EXPECT_TRUE(names(read_error(b), "/bufferViews/0/byteLength")) << read_error(b);
}

TEST(GltfAccessors, aStrideShorterThanAnElementIsRefused) {
    GltfBuilder b = triangle();
    b.document["bufferViews"][0]["byteStride"] = 8;
    EXPECT_TRUE(names(read_error(b), "/bufferViews/0/byteStride: 8 bytes between elements of 12 bytes")) << read_error(b);
}

TEST(GltfAccessors, aStrideSkipsTheBytesBetweenElements) {
    GltfBuilder b;
    // Three positions 16 bytes apart, a fourth float of padding after each.
    const int p = b.accessor(std::vector<float>{0, 0, 0, -9, 1, 0, 0, -9, 0, 1, 0, -9}, "VEC3", 5126);
    b.document["accessors"][p]["count"] = 3;
    b.document["bufferViews"][0]["byteStride"] = 16;
    b.node({{"mesh", b.mesh({{"attributes", {{"POSITION", p}}}})}});
    const Scene scene = read_built(b);
    ASSERT_EQ(scene.meshes[0].data->positions.size(), 3u);
    EXPECT_EQ(scene.meshes[0].data->positions[1], glm::vec3(1, 0, 0));
    EXPECT_EQ(scene.meshes[0].data->positions[2], glm::vec3(0, 1, 0));
}

TEST(GltfAccessors, anIndexPastTheVerticesIsRefused) {
    GltfBuilder b = triangle();
    b.document["meshes"][0]["primitives"][0]["indices"] = b.accessor(std::vector<uint16_t>{0, 1, 3}, "SCALAR", 5123);
    EXPECT_TRUE(names(read_error(b), "/accessors/1: index 3 (element 2) is past the primitive's 3 vertices")) << read_error(b);
}

TEST(GltfAccessors, indicesOfEachWidthAreRead) {
    for (const int type : {5121, 5123, 5125}) {
        GltfBuilder b = triangle();
        int indices = -1;
        if (type == 5121) indices = b.accessor(std::vector<uint8_t>{2, 1, 0}, "SCALAR", type);
        if (type == 5123) indices = b.accessor(std::vector<uint16_t>{2, 1, 0}, "SCALAR", type);
        if (type == 5125) indices = b.accessor(std::vector<uint32_t>{2, 1, 0}, "SCALAR", type);
        b.document["meshes"][0]["primitives"][0]["indices"] = indices;
        const Scene scene = read_built(b);
        // No normals: the corners become vertices in order, so the first is the old vertex 2.
        EXPECT_EQ(scene.meshes[0].data->positions[0], glm::vec3(0, 1, 0)) << type;
    }
}

TEST(GltfAccessors, signedOrFloatIndicesAreRefused) {
    GltfBuilder b = triangle();
    b.document["meshes"][0]["primitives"][0]["indices"] = b.accessor(std::vector<float>{0, 1, 2}, "SCALAR", 5126);
    EXPECT_TRUE(names(read_error(b), "/accessors/1/componentType")) << read_error(b);
}

TEST(GltfAccessors, theWrongElementTypeOrAMissingAccessorIsRefused) {
    GltfBuilder b = triangle();
    b.document["accessors"][0]["type"] = "VEC2";
    b.document["accessors"][0]["count"] = 4;
    EXPECT_TRUE(names(read_error(b), "/accessors/0/type")) << read_error(b);
    GltfBuilder missing = triangle();
    missing.document["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = 5;
    EXPECT_TRUE(names(read_error(missing), "/meshes/0/primitives/0/attributes/POSITION: there is no accessor 5"))
        << read_error(missing);
}

TEST(GltfAccessors, sparseAccessorsAreRefused) {
    GltfBuilder b = triangle();
    b.document["accessors"][0]["sparse"] = {{"count", 1},
                                            {"indices", {{"bufferView", 0}, {"componentType", 5125}}},
                                            {"values", {{"bufferView", 0}}}};
    EXPECT_TRUE(names(read_error(b), "/accessors/0/sparse")) << read_error(b);
}

TEST(GltfAccessors, aNonFiniteFloatIsRefused) {
    GltfBuilder b;
    const int p = b.positions({0, 0, 0, std::numeric_limits<float>::quiet_NaN(), 0, 0, 0, 1, 0});
    b.node({{"mesh", b.mesh({{"attributes", {{"POSITION", p}}}})}});
    EXPECT_TRUE(names(read_error(b), "/accessors/0: element 1 is not a finite number")) << read_error(b);
}

TEST(GltfAccessors, anAccessorWithoutAViewIsZeros) {
    GltfBuilder b = triangle();
    b.document["accessors"].push_back({{"componentType", 5126}, {"count", 3}, {"type", "VEC3"}});
    b.document["meshes"][0]["primitives"][0]["attributes"]["NORMAL"] = 1;
    const Scene scene = read_built(b);
    ASSERT_EQ(scene.meshes[0].data->normals.size(), 3u);
    EXPECT_EQ(scene.meshes[0].data->normals[2], glm::vec3(0.0f));
}

TEST(GltfAccessors, normalizedIntegersMapToTheUnitInterval) {
    GltfBuilder b = triangle();
    b.document["meshes"][0]["primitives"][0]["attributes"]["COLOR_0"] =
        b.accessor(std::vector<uint16_t>{65535, 0, 32768, 0, 65535, 0, 0, 0, 65535}, "VEC3", 5123, true);
    const Scene scene = read_built(b);
    EXPECT_FLOAT_EQ(scene.meshes[0].data->colors[0].x, 1.0f);
    EXPECT_FLOAT_EQ(scene.meshes[0].data->colors[0].z, 32768.0f / 65535.0f);

    // The same integers without `normalized` are not colours.
    GltfBuilder raw = triangle();
    raw.document["meshes"][0]["primitives"][0]["attributes"]["COLOR_0"] =
        raw.accessor(std::vector<uint16_t>{65535, 0, 32768, 0, 65535, 0, 0, 0, 65535}, "VEC3", 5123);
    EXPECT_TRUE(names(read_error(raw), "/accessors/1/componentType")) << read_error(raw);
}

TEST(GltfAccessors, anAttributeWithAnotherCountThanThePositionsIsRefused) {
    GltfBuilder b = triangle();
    b.document["meshes"][0]["primitives"][0]["attributes"]["NORMAL"] =
        b.accessor(std::vector<float>{0, 0, 1, 0, 0, 1}, "VEC3", 5126);
    EXPECT_TRUE(names(read_error(b), "attributes/NORMAL: 2 elements for 3 positions")) << read_error(b);
}

}  // namespace
}  // namespace raster
