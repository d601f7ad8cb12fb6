// PLY loader tests on input it reads: ascii and binary little-endian bodies, skipping of unknown data, files on disk
// (mesh_ply_rejection_test has the inputs it refuses).
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <type_traits>
#include <vector>

#include <gtest/gtest.h>

#include "raster/core/errors.h"
#include "raster/formats/mesh_ply.h"

namespace {

using raster::InputError;
using raster::MeshData;
using raster::parse_ply;

testing::AssertionResult contains(const std::string& text, const std::string& part) {
    if (text.find(part) != std::string::npos) return testing::AssertionSuccess();
    return testing::AssertionFailure() << "'" << text << "' does not contain '" << part << "'";
}

// Little-endian byte writer for hand-made binary bodies, independent of the host byte order.
struct Bytes {
    std::string data;

    template <class T>
    Bytes& put(T value) {
        static_assert(std::is_arithmetic_v<T>);
        using Bits = std::conditional_t<sizeof(T) == 1, uint8_t,
                     std::conditional_t<sizeof(T) == 2, uint16_t, std::conditional_t<sizeof(T) == 4, uint32_t, uint64_t>>>;
        const auto bits = std::bit_cast<Bits>(value);
        for (size_t i = 0; i < sizeof(T); ++i) data += static_cast<char>((bits >> (8 * i)) & 0xff);
        return *this;
    }
    Bytes& f32(float v) { return put(v); }
    Bytes& u8(uint8_t v) { return put(v); }
    Bytes& i32(int32_t v) { return put(v); }
};

void expect_vec3(const glm::vec3& v, float x, float y, float z) {
    EXPECT_FLOAT_EQ(v.x, x);
    EXPECT_FLOAT_EQ(v.y, y);
    EXPECT_FLOAT_EQ(v.z, z);
}

void expect_triangle(const raster::TriangleIndices& t, uint32_t a, uint32_t b, uint32_t c) {
    EXPECT_EQ(t.v[0], a);
    EXPECT_EQ(t.v[1], b);
    EXPECT_EQ(t.v[2], c);
}

const std::string kTetrahedron =
    "ply\n"
    "format ascii 1.0\n"
    "comment a unit tetrahedron\n"
    "obj_info made by hand\n"
    "element vertex 4\n"
    "property float x\n"
    "property float y\n"
    "property float z\n"
    "property uchar red\n"
    "property uchar green\n"
    "property uchar blue\n"
    "element face 4\n"
    "property list uchar int vertex_indices\n"
    "end_header\n"
    "0 0 0 255 0 0\n"
    "1 0 0 0 255 0\n"
    "0 1 0 0 0 255\n"
    "0 0 1.5 128 64 255\n"
    "3 0 2 1\n"
    "3 0 1 3\n"
    "3 0 3 2\n"
    "3 1 2 3\n";

// Header for a binary vertex/face file with float xyz, uchar count and int indices.
std::string binary_header(int vertices, int faces, const std::string& extra_vertex_properties = "") {
    return "ply\nformat binary_little_endian 1.0\nelement vertex " + std::to_string(vertices) +
           "\nproperty float x\nproperty float y\nproperty float z\n" + extra_vertex_properties + "element face " +
           std::to_string(faces) + "\nproperty list uchar int vertex_indices\nend_header\n";
}

// ------------------------------------------------------------------------------------------------ parsing

TEST(PlyLoader, readsAsciiTetrahedron) {
    const MeshData mesh = parse_ply(kTetrahedron, "meshes/tetra.ply");
    ASSERT_EQ(mesh.positions.size(), 4u);
    expect_vec3(mesh.positions[0], 0, 0, 0);
    expect_vec3(mesh.positions[1], 1, 0, 0);
    expect_vec3(mesh.positions[2], 0, 1, 0);
    expect_vec3(mesh.positions[3], 0, 0, 1.5f);
    ASSERT_EQ(mesh.colors.size(), 4u);
    expect_vec3(mesh.colors[0], 1.0f, 0.0f, 0.0f);
    expect_vec3(mesh.colors[1], 0.0f, 1.0f, 0.0f);
    expect_vec3(mesh.colors[2], 0.0f, 0.0f, 1.0f);
    expect_vec3(mesh.colors[3], 128.0f / 255.0f, 64.0f / 255.0f, 1.0f);
    ASSERT_EQ(mesh.triangles.size(), 4u);
    expect_triangle(mesh.triangles[0], 0, 2, 1);
    expect_triangle(mesh.triangles[1], 0, 1, 3);
    expect_triangle(mesh.triangles[2], 0, 3, 2);
    expect_triangle(mesh.triangles[3], 1, 2, 3);
    EXPECT_TRUE(mesh.normals.empty());
    EXPECT_TRUE(mesh.face_colors.empty());
    ASSERT_EQ(mesh.object_names.size(), 1u);
    EXPECT_EQ(mesh.object_names[0], "tetra");
    ASSERT_EQ(mesh.object_first_triangle.size(), 1u);
    EXPECT_EQ(mesh.object_first_triangle[0], 0u);
}

TEST(PlyLoader, readsBinaryLittleEndianWithFloatColoursAndNormals) {
    std::string text = binary_header(3, 1,
                                     "property float nx\nproperty float ny\nproperty float nz\n"
                                     "property float red\nproperty float green\nproperty float blue\n");
    Bytes body;
    body.f32(0).f32(0).f32(0).f32(0).f32(0).f32(1).f32(0.25f).f32(0.5f).f32(1.0f);
    body.f32(2).f32(0).f32(0).f32(0).f32(1).f32(0).f32(1.5f).f32(-0.5f).f32(0.0f);  // colours clamp to [0,1]
    body.f32(0).f32(-3).f32(0.5f).f32(1).f32(0).f32(0).f32(0.0f).f32(0.0f).f32(0.75f);
    body.u8(3).i32(2).i32(1).i32(0);
    text += body.data;

    const MeshData mesh = parse_ply(text, "bin.ply");
    ASSERT_EQ(mesh.positions.size(), 3u);
    expect_vec3(mesh.positions[0], 0, 0, 0);
    expect_vec3(mesh.positions[1], 2, 0, 0);
    expect_vec3(mesh.positions[2], 0, -3, 0.5f);
    ASSERT_EQ(mesh.normals.size(), 3u);
    expect_vec3(mesh.normals[0], 0, 0, 1);
    expect_vec3(mesh.normals[1], 0, 1, 0);
    expect_vec3(mesh.normals[2], 1, 0, 0);
    ASSERT_EQ(mesh.colors.size(), 3u);
    expect_vec3(mesh.colors[0], 0.25f, 0.5f, 1.0f);
    expect_vec3(mesh.colors[1], 1.0f, 0.0f, 0.0f);
    expect_vec3(mesh.colors[2], 0.0f, 0.0f, 0.75f);
    ASSERT_EQ(mesh.triangles.size(), 1u);
    expect_triangle(mesh.triangles[0], 2, 1, 0);
    EXPECT_EQ(mesh.object_names, std::vector<std::string>{"bin"});
}

// Blender 2.4x writes its banner without 'comment': read as one, with a warning naming the file and line. A line
// that only looks like it ("Created" alone, or another word) is still refused.
TEST(PlyLoader, readsBlender24xCreatedByLineAsACommentWithAWarning) {
    std::string blender = kTetrahedron;
    blender.insert(blender.find("element vertex"),
                   "Created by Blender 2.49 (sub 2) - www.blender.org, source file: 'tetra.blend'\n");
    testing::internal::CaptureStderr();
    const MeshData mesh = parse_ply(blender, "meshes/tetra.ply");
    const std::string warning = testing::internal::GetCapturedStderr();
    EXPECT_TRUE(contains(warning, "meshes/tetra.ply:5: warning:"));
    EXPECT_TRUE(contains(warning, "Created by"));
    const MeshData plain = parse_ply(kTetrahedron, "meshes/tetra.ply");
    EXPECT_EQ(mesh.positions, plain.positions);
    EXPECT_EQ(mesh.colors, plain.colors);
    ASSERT_EQ(mesh.triangles.size(), plain.triangles.size());
    for (const char* near_miss : {"Created\n", "Created with Blender\n", "created by Blender\n"}) {
        std::string refused = kTetrahedron;
        refused.insert(refused.find("element vertex"), near_miss);
        EXPECT_THROW(parse_ply(refused, "meshes/tetra.ply"), InputError) << near_miss;
    }
}

TEST(PlyLoader, triangulatesQuadAndPentagonAsFans) {
    const std::string text =
        "ply\nformat ascii 1.0\nelement vertex 5\nproperty float x\nproperty float y\nproperty float z\n"
        "element face 2\nproperty list uchar uint vertex_index\nend_header\n"
        "0 0 0\n1 0 0\n1 1 0\n0 1 0\n0.5 1.5 0\n"
        "4 3 0 1 2\n"
        "5 0 1 2 4 3\n";
    const MeshData mesh = parse_ply(text, "quad.ply");
    ASSERT_EQ(mesh.triangles.size(), 5u);
    expect_triangle(mesh.triangles[0], 3, 0, 1);
    expect_triangle(mesh.triangles[1], 3, 1, 2);
    expect_triangle(mesh.triangles[2], 0, 1, 2);
    expect_triangle(mesh.triangles[3], 0, 2, 4);
    expect_triangle(mesh.triangles[4], 0, 4, 3);
}

TEST(PlyLoader, skipsUnknownPropertiesAndElementsInAscii) {
    const std::string text =
        "ply\nformat ascii 1.0\n"
        "element vertex 3\n"
        "property double confidence\n"
        "property float x\n"
        "property list uchar float tags\n"
        "property float y\n"
        "property float z\n"
        "property uchar alpha\n"
        "element edge 2\n"
        "property int vertex1\n"
        "property list ushort double weights\n"
        "element face 1\n"
        "property int flags\n"
        "property list uchar int vertex_indices\n"
        "property list uchar float texcoord\n"
        "element material 0\n"
        "property uchar ambient_red\n"
        "end_header\n"
        "0.9 1 2 7.5 8.5 5 6 255\n"
        "0.8 4 0 5 6\t1\r\n"
        "0.7 7 3 1 2 3 8 9 0\n"
        "0 3 1.0 2.0 3.0\n"
        "1 0\n"
        "  42 3 0 1 2 6 0 0 1 0 0 1  \n";
    const MeshData mesh = parse_ply(text, "skip.ply");
    ASSERT_EQ(mesh.positions.size(), 3u);
    expect_vec3(mesh.positions[0], 1, 5, 6);  // the two tag floats after "2" are not y and z
    expect_vec3(mesh.positions[1], 4, 5, 6);
    expect_vec3(mesh.positions[2], 7, 8, 9);
    ASSERT_EQ(mesh.triangles.size(), 1u);
    expect_triangle(mesh.triangles[0], 0, 1, 2);
    EXPECT_TRUE(mesh.colors.empty());  // alpha alone is not a colour
    EXPECT_TRUE(mesh.normals.empty());
}

TEST(PlyLoader, skipsUnknownPropertiesAndElementsInBinary) {
    std::string text =
        "ply\nformat binary_little_endian 1.0\n"
        "element vertex 3\n"
        "property double confidence\n"
        "property float x\n"
        "property list uchar float tags\n"
        "property float y\n"
        "property float z\n"
        "property uchar alpha\n"
        "element edge 2\n"
        "property int vertex1\n"
        "property list ushort double weights\n"
        "element face 1\n"
        "property short flags\n"
        "property list uchar int vertex_indices\n"
        "property list int float texcoord\n"
        "end_header\n";
    Bytes b;
    b.put(0.9).f32(1).u8(2).f32(7.5f).f32(8.5f).f32(5).f32(6).u8(255);
    b.put(0.8).f32(4).u8(0).f32(5).f32(6).u8(1);
    b.put(0.7).f32(7).u8(3).f32(1).f32(2).f32(3).f32(8).f32(9).u8(0);
    b.i32(0).put(uint16_t{3}).put(1.0).put(2.0).put(3.0);
    b.i32(1).put(uint16_t{0});
    b.put(int16_t{42}).u8(3).i32(0).i32(1).i32(2).i32(2).f32(0).f32(1);
    text += b.data;
    const MeshData mesh = parse_ply(text, "skip.ply");
    ASSERT_EQ(mesh.positions.size(), 3u);
    expect_vec3(mesh.positions[0], 1, 5, 6);
    expect_vec3(mesh.positions[1], 4, 5, 6);
    expect_vec3(mesh.positions[2], 7, 8, 9);
    ASSERT_EQ(mesh.triangles.size(), 1u);
    expect_triangle(mesh.triangles[0], 0, 1, 2);
    EXPECT_TRUE(mesh.colors.empty());
}

TEST(PlyLoader, storesFaceColoursOncePerOutputTriangle) {
    const std::string text =
        "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
        "element face 2\nproperty list uchar int vertex_indices\n"
        "property uchar red\nproperty uchar green\nproperty uchar blue\nend_header\n"
        "0 0 0\n1 0 0\n1 1 0\n0 1 0\n"
        "4 0 1 2 3 255 128 0\n"
        "3 0 2 3 0 0 51\n";
    const MeshData mesh = parse_ply(text, "fc.ply");
    ASSERT_EQ(mesh.triangles.size(), 3u);
    ASSERT_EQ(mesh.face_colors.size(), 3u);
    expect_vec3(mesh.face_colors[0], 1.0f, 128.0f / 255.0f, 0.0f);
    expect_vec3(mesh.face_colors[1], 1.0f, 128.0f / 255.0f, 0.0f);
    expect_vec3(mesh.face_colors[2], 0.0f, 0.0f, 0.2f);
    EXPECT_TRUE(mesh.colors.empty());
}

TEST(PlyLoader, readsCrlfHeaderInAsciiAndBinary) {
    std::string ascii = kTetrahedron;
    for (size_t pos = 0; (pos = ascii.find('\n', pos)) != std::string::npos; pos += 2) ascii.replace(pos, 1, "\r\n");
    const MeshData a = parse_ply(ascii, "crlf.ply");
    ASSERT_EQ(a.positions.size(), 4u);
    expect_vec3(a.positions[3], 0, 0, 1.5f);
    expect_vec3(a.colors[3], 128.0f / 255.0f, 64.0f / 255.0f, 1.0f);
    ASSERT_EQ(a.triangles.size(), 4u);
    expect_triangle(a.triangles[3], 1, 2, 3);

    std::string binary = binary_header(3, 1);
    for (size_t pos = 0; (pos = binary.find('\n', pos)) != std::string::npos; pos += 2) binary.replace(pos, 1, "\r\n");
    Bytes b;
    b.f32(10).f32(0).f32(0).f32(0).f32(1).f32(0).f32(0).f32(0).f32(1).u8(3).i32(0).i32(1).i32(2);
    const MeshData m = parse_ply(binary + b.data, "crlf_bin.ply");
    ASSERT_EQ(m.positions.size(), 3u);
    expect_vec3(m.positions[0], 10, 0, 0);  // the body starts right after "end_header\r\n"
    ASSERT_EQ(m.triangles.size(), 1u);
    expect_triangle(m.triangles[0], 0, 1, 2);
}

TEST(PlyLoader, acceptsSizedTypeAliasesAndIntegerCoordinates) {
    std::string text =
        "ply\nformat binary_little_endian 1.0\nelement vertex 3\n"
        "property int16 x\nproperty float64 y\nproperty int8 z\n"
        "property uint16 red\nproperty uint8 green\nproperty float32 blue\n"
        "element face 1\nproperty list uint8 uint32 vertex_indices\nend_header\n";
    Bytes b;
    b.put(int16_t{-300}).put(0.5).put(int8_t{-7}).put(uint16_t{65535}).u8(51).f32(0.5f);
    b.put(int16_t{1}).put(0.0).put(int8_t{0}).put(uint16_t{0}).u8(0).f32(0.0f);
    b.put(int16_t{0}).put(1.0).put(int8_t{0}).put(uint16_t{0}).u8(0).f32(0.0f);
    b.u8(3).put(uint32_t{0}).put(uint32_t{1}).put(uint32_t{2});
    const MeshData mesh = parse_ply(text + b.data, "alias.ply");
    ASSERT_EQ(mesh.positions.size(), 3u);
    expect_vec3(mesh.positions[0], -300, 0.5f, -7);
    ASSERT_EQ(mesh.colors.size(), 3u);
    expect_vec3(mesh.colors[0], 1.0f, 0.2f, 0.5f);
}

TEST(PlyLoader, storesNoOptionalAttributesWhenAbsentAndAcceptsPointClouds) {
    const std::string triangle =
        "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
        "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
    const MeshData tri = parse_ply(triangle, "t.ply");
    EXPECT_EQ(tri.positions.size(), 3u);
    EXPECT_EQ(tri.triangles.size(), 1u);
    EXPECT_TRUE(tri.colors.empty());
    EXPECT_TRUE(tri.normals.empty());
    EXPECT_TRUE(tri.face_colors.empty());

    const std::string cloud =
        "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\nproperty float z\n"
        "end_header\n1 2 3\n4 5 6\n\n";
    const MeshData pts = parse_ply(cloud, "cloud.ply");
    ASSERT_EQ(pts.positions.size(), 2u);
    expect_vec3(pts.positions[1], 4, 5, 6);
    EXPECT_TRUE(pts.triangles.empty());
}

TEST(PlyLoader, loadPlyReadsFileAndNamesObjectAfterStem) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "raster_mesh_ply_test";
    std::filesystem::create_directories(dir);
    const std::filesystem::path file = dir / "little_tetra.ply";
    {
        std::ofstream out(file, std::ios::binary);
        out << kTetrahedron;
    }
    const MeshData mesh = raster::load_ply(file);
    EXPECT_EQ(mesh.positions.size(), 4u);
    EXPECT_EQ(mesh.triangles.size(), 4u);
    EXPECT_EQ(mesh.object_names, std::vector<std::string>{"little_tetra"});
    std::filesystem::remove_all(dir);
}

// ------------------------------------------------------------------------------------------- files it cannot read

TEST(PlyLoader, loadPlyErrorNamesMissingFile) {
    const std::filesystem::path missing = std::filesystem::temp_directory_path() / "raster_no_such_dir" / "gone.ply";
    try {
        raster::load_ply(missing);
        ADD_FAILURE() << "no InputError thrown";
    } catch (const InputError& e) {
        EXPECT_EQ(e.file(), missing.string());
        EXPECT_TRUE(contains(e.what(), "gone.ply"));
        EXPECT_TRUE(contains(e.what(), "cannot open"));
    }
}

TEST(PlyLoader, loadPlyErrorNamesFileForFormatErrors) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "raster_mesh_ply_test_bad";
    std::filesystem::create_directories(dir);
    const std::filesystem::path file = dir / "bad.ply";
    {
        std::ofstream out(file, std::ios::binary);
        out << "ply\nformat ascii 1.0\nelement vertex 1\nproperty flot x\nend_header\n";
    }
    try {
        raster::load_ply(file);
        ADD_FAILURE() << "no InputError thrown";
    } catch (const InputError& e) {
        EXPECT_EQ(e.file(), file.string());
        EXPECT_EQ(e.line(), 4);
        EXPECT_TRUE(contains(e.what(), file.string() + ":4:"));
    }
    std::filesystem::remove_all(dir);
}

TEST(PlyLoader, loadPlyRejectsDirectoriesAndFilesOver2GiB) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "raster_mesh_ply_test_big";
    std::filesystem::create_directories(dir);
    try {
        raster::load_ply(dir);
        ADD_FAILURE() << "no InputError thrown for a directory";
    } catch (const InputError& e) {
        EXPECT_EQ(e.file(), dir.string());
        EXPECT_TRUE(contains(e.what(), "directory"));
    }
    const std::filesystem::path big = dir / "big.ply";
    { std::ofstream out(big, std::ios::binary); }
    std::filesystem::resize_file(big, (uint64_t{1} << 31) + 1);  // sparse: nothing is written or read
    try {
        raster::load_ply(big);
        ADD_FAILURE() << "no InputError thrown for a file over 2 GiB";
    } catch (const InputError& e) {
        EXPECT_EQ(e.file(), big.string());
        EXPECT_TRUE(contains(e.what(), "too large"));
    }
    std::filesystem::remove_all(dir);
}

// Texture coordinates under each name exporters give them, kept per triangle corner; given in part they are an
// error naming the vertex element's line.
TEST(PlyLoader, readsTextureCoordinatesUnderEachExportersNames) {
    for (const auto& [u, v] : {std::pair{"u", "v"}, {"s", "t"}, {"texture_u", "texture_v"}}) {
        const std::string text = std::string("ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
                                             "property float z\nproperty float ") + u + "\nproperty float " + v +
                                 "\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
                                 "0 0 0 0 0\n1 0 0 1 0\n1 1 0 1 1\n0 1 0 0 0.5\n4 0 1 2 3\n";
        const MeshData mesh = parse_ply(text, "uv.ply");
        ASSERT_EQ(mesh.corner_uvs.size(), 2u) << u;
        EXPECT_EQ(mesh.corner_uvs[1].uv[2], glm::vec2(0.0f, 0.5f)) << u;  // the fan's second triangle: 0 2 3
    }
    try {
        parse_ply("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\n"
                  "property float u\nend_header\n0 0 0 0\n", "half.ply");
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_EQ(e.line(), 3);
        EXPECT_NE(e.message().find("one u"), std::string::npos) << e.message();
    }
}

}  // namespace
