// glTF primitives: lists, strips and fans numbered as the spec numbers them, trailing list indices dropped, points
// and lines left out, flat normals by giving every triangle its own corners, and texture coordinates turned to
// raster's v-up convention.
#include "raster/gltf/gltf_primitive.h"

#include <gtest/gtest.h>

#include "tests/support/gltf_builder.h"

namespace raster {
namespace {

using test_support::GltfBuilder;

std::vector<std::array<uint32_t, 3>> corners(const std::vector<TriangleIndices>& triangles) {
    std::vector<std::array<uint32_t, 3>> out;
    for (const TriangleIndices& t : triangles) out.push_back({t.v[0], t.v[1], t.v[2]});
    return out;
}
using Corners = std::vector<std::array<uint32_t, 3>>;

TEST(GltfPrimitive, listsStripsAndFansAreNumberedAsTheSpecSays) {
    const std::vector<uint32_t> i{10, 11, 12, 13, 14};
    // A list: whole triples; the last two indices make nothing.
    EXPECT_EQ(corners(gltf_triangles(4, i)), (Corners{{10, 11, 12}}));
    // A strip: every other triangle swaps its last two, so all wind alike.
    EXPECT_EQ(corners(gltf_triangles(5, i)), (Corners{{10, 11, 12}, {11, 13, 12}, {12, 13, 14}}));
    // A fan: about the first index.
    EXPECT_EQ(corners(gltf_triangles(6, i)), (Corners{{11, 12, 10}, {12, 13, 10}, {13, 14, 10}}));
    EXPECT_TRUE(gltf_triangles(5, {1, 2}).empty());
}

struct Read {
    GltfBuilder builder;
    tinygltf::Model model;
    std::optional<MeshData> mesh;
};

// The builder's mesh 0 primitive 0 read with `material`.
Read read(GltfBuilder builder, const GltfMaterial& material) {
    Read out{std::move(builder), {}, {}};
    out.model = parse_gltf_model(out.builder.text(), "model.gltf", test_support::no_files());
    GltfAccessorReader reader(out.model, "model.gltf");
    GltfWarnings warnings("model.gltf");
    out.mesh = read_gltf_primitive(reader, out.model.meshes[0].primitives[0], "/meshes/0/primitives/0", material, warnings);
    return out;
}

GltfBuilder quad(bool normals) {
    GltfBuilder b;
    nlohmann::json attributes = {{"POSITION", b.positions({0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0})}};
    if (normals) attributes["NORMAL"] = b.accessor(std::vector<float>{0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1}, "VEC3", 5126);
    attributes["TEXCOORD_0"] = b.accessor(std::vector<float>{0, 1, 1, 1, 1, 0, 0.25f, 0.125f}, "VEC2", 5126);
    const int indices = b.accessor(std::vector<uint8_t>{0, 1, 2, 0, 2, 3}, "SCALAR", 5121);
    b.node({{"mesh", b.mesh({{"attributes", attributes}, {"indices", indices}})}});
    return b;
}

TEST(GltfPrimitive, withNormalsTheVerticesAreSharedAndWithoutEachTriangleHasItsOwn) {
    const Read shared = read(quad(true), GltfMaterial{});
    ASSERT_TRUE(shared.mesh);
    EXPECT_EQ(shared.mesh->positions.size(), 4u);
    EXPECT_EQ(corners(shared.mesh->triangles), (Corners{{0, 1, 2}, {0, 2, 3}}));

    const Read flat = read(quad(false), GltfMaterial{});
    ASSERT_TRUE(flat.mesh);
    EXPECT_TRUE(flat.mesh->normals.empty());
    EXPECT_EQ(corners(flat.mesh->triangles), (Corners{{0, 1, 2}, {3, 4, 5}}));
    EXPECT_EQ(flat.mesh->positions[4], glm::vec3(1, 1, 0));  // the second triangle's middle corner, old vertex 2
}

TEST(GltfPrimitive, textureCoordinatesAreKeptForATexturedMaterialWithVUp) {
    GltfMaterial textured;
    textured.material.texture = TextureBinding{};
    const Read r = read(quad(true), textured);
    ASSERT_EQ(r.mesh->corner_uvs.size(), 2u);
    // Vertex 3's (0.25, 0.125), v measured down from the image's top, is (0.25, 0.875) measured up.
    EXPECT_EQ(r.mesh->corner_uvs[1].uv[2], glm::vec2(0.25f, 0.875f));
    EXPECT_EQ(r.mesh->corner_uvs[0].uv[0], glm::vec2(0.0f, 0.0f));
    // An untextured material keeps none.
    EXPECT_TRUE(read(quad(true), GltfMaterial{}).mesh->corner_uvs.empty());
}

TEST(GltfPrimitive, pointsAndLinesAreNotTriangles) {
    for (const int mode : {0, 1, 2, 3}) {
        GltfBuilder b = GltfBuilder::one_triangle();
        b.document["meshes"][0]["primitives"][0]["mode"] = mode;
        EXPECT_FALSE(read(b, GltfMaterial{}).mesh) << mode;
    }
    GltfBuilder bad = GltfBuilder::one_triangle();
    bad.document["meshes"][0]["primitives"][0]["mode"] = 7;
    EXPECT_THROW(read(bad, GltfMaterial{}), InputError);
}

TEST(GltfPrimitive, aPrimitiveWithoutPositionsIsRefused) {
    GltfBuilder b = GltfBuilder::one_triangle();
    b.document["meshes"][0]["primitives"][0]["attributes"] = {{"NORMAL", 0}};
    try {
        read(b, GltfMaterial{});
        FAIL() << "read a primitive without POSITION";
    } catch (const InputError& e) {
        EXPECT_NE(e.message().find("/meshes/0/primitives/0/attributes: has no POSITION"), std::string::npos) << e.message();
    }
}

}  // namespace
}  // namespace raster
