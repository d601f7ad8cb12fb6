// PLY loader tests: ascii and binary little-endian parsing, skipping of unknown data, and one test per error class.
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
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

// The outcome of parsing input that must be rejected.
struct Failure {
    bool thrown = false;
    int line = -1;
    std::string what;
};

Failure parse_failure(const std::string& bytes) {
    Failure f;
    try {
        parse_ply(bytes, "test.ply");
    } catch (const InputError& e) {
        f.thrown = true;
        f.line = e.line();
        f.what = e.what();
    }
    return f;
}

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

// A tiny ascii file: one triangle, vertex block given, used by the error tests (line 10 is the first vertex).
std::string ascii_triangle(const std::string& vertex_lines, const std::string& face_lines = "3 0 1 2\n",
                           int vertices = 3, int faces = 1) {
    return "ply\nformat ascii 1.0\nelement vertex " + std::to_string(vertices) +
           "\nproperty float x\nproperty float y\nproperty float z\nelement face " + std::to_string(faces) +
           "\nproperty list uchar int vertex_indices\nend_header\n" + vertex_lines + face_lines;
}

const std::string kTriangleVertices = "0 0 0\n1 0 0\n0 1 0\n";  // lines 10..12; the face is line 13

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
    const MeshData tri = parse_ply(ascii_triangle(kTriangleVertices), "t.ply");
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

// ------------------------------------------------------------------------------------------------ errors

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

TEST(PlyLoader, rejectsMissingMagic) {
    for (const std::string text : {"", "plx\nformat ascii 1.0\n", "PLY\n", "\nply\n", "format ascii 1.0\nend_header\n"}) {
        const Failure f = parse_failure(text);
        EXPECT_TRUE(f.thrown) << text;
        EXPECT_EQ(f.line, 1) << text;
        EXPECT_TRUE(contains(f.what, "magic")) << text;
    }
}

TEST(PlyLoader, rejectsUnknownFormat) {
    const Failure f = parse_failure("ply\nformat utf8 1.0\nelement vertex 0\nend_header\n");
    EXPECT_TRUE(f.thrown);
    EXPECT_EQ(f.line, 2);
    EXPECT_TRUE(contains(f.what, "unknown PLY format 'utf8'"));

    const Failure version = parse_failure("ply\nformat ascii 2.0\nend_header\n");
    EXPECT_TRUE(version.thrown);
    EXPECT_EQ(version.line, 2);
    EXPECT_TRUE(contains(version.what, "version"));

    const Failure none = parse_failure("ply\nelement vertex 0\nproperty float x\nend_header\n");
    EXPECT_TRUE(none.thrown);
    EXPECT_EQ(none.line, 4);
    EXPECT_TRUE(contains(none.what, "format"));
}

TEST(PlyLoader, rejectsBigEndianAsUnsupported) {
    const Failure f = parse_failure(
        "ply\nformat binary_big_endian 1.0\nelement vertex 0\nproperty float x\nend_header\n");
    EXPECT_TRUE(f.thrown);
    EXPECT_EQ(f.line, 2);
    EXPECT_TRUE(contains(f.what, "unsupported"));
    EXPECT_TRUE(contains(f.what, "binary_big_endian"));
}

TEST(PlyLoader, rejectsUnknownType) {
    const Failure scalar = parse_failure(
        "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty real y\nend_header\n");
    EXPECT_TRUE(scalar.thrown);
    EXPECT_EQ(scalar.line, 5);
    EXPECT_TRUE(contains(scalar.what, "unknown property type 'real'"));

    const Failure list = parse_failure(
        "ply\nformat ascii 1.0\nelement face 1\nproperty list uchar int64 vertex_indices\nend_header\n");
    EXPECT_TRUE(list.thrown);
    EXPECT_EQ(list.line, 4);
    EXPECT_TRUE(contains(list.what, "unknown property type 'int64'"));

    const Failure float_count = parse_failure(
        "ply\nformat ascii 1.0\nelement face 1\nproperty list float int vertex_indices\nend_header\n");
    EXPECT_TRUE(float_count.thrown);
    EXPECT_EQ(float_count.line, 4);
    EXPECT_TRUE(contains(float_count.what, "count type"));
}

TEST(PlyLoader, rejectsMalformedHeaderLines) {
    const Failure keyword = parse_failure("ply\nformat ascii 1.0\nelemnt vertex 1\nend_header\n");
    EXPECT_TRUE(keyword.thrown);
    EXPECT_EQ(keyword.line, 3);
    EXPECT_TRUE(contains(keyword.what, "unknown header keyword 'elemnt'"));

    const Failure orphan = parse_failure("ply\nformat ascii 1.0\nproperty float x\nend_header\n");
    EXPECT_TRUE(orphan.thrown);
    EXPECT_EQ(orphan.line, 3);
    EXPECT_TRUE(contains(orphan.what, "before any 'element'"));

    const Failure no_end = parse_failure("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n");
    EXPECT_TRUE(no_end.thrown);
    EXPECT_TRUE(contains(no_end.what, "end_header"));

    const Failure no_xyz = parse_failure("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nend_header\n0\n");
    EXPECT_TRUE(no_xyz.thrown);
    EXPECT_EQ(no_xyz.line, 3);
    EXPECT_TRUE(contains(no_xyz.what, "x, y and z"));
}

TEST(PlyLoader, rejectsTruncatedAsciiBody) {
    const Failure f = parse_failure(ascii_triangle("0 0 0\n1 0 0\n", ""));
    EXPECT_TRUE(f.thrown);
    EXPECT_EQ(f.line, 12);
    EXPECT_TRUE(contains(f.what, "truncated"));

    const Failure short_line = parse_failure(ascii_triangle("0 0 0\n1 0\n0 1 0\n"));
    EXPECT_TRUE(short_line.thrown);
    EXPECT_EQ(short_line.line, 11);
    EXPECT_TRUE(contains(short_line.what, "line ends early"));
}

TEST(PlyLoader, rejectsTruncatedBinaryBody) {
    Bytes b;
    b.f32(0).f32(0).f32(0).f32(1).f32(0).f32(0).f32(0).f32(1).f32(0).u8(3).i32(0).i32(1);  // last index missing
    const std::string header = binary_header(3, 1);
    const Failure f = parse_failure(header + b.data);
    EXPECT_TRUE(f.thrown);
    EXPECT_EQ(f.line, 0);
    EXPECT_TRUE(contains(f.what, "truncated"));
    EXPECT_TRUE(contains(f.what, "byte offset " + std::to_string(header.size() + b.data.size())));
}

TEST(PlyLoader, rejectsCountsTheBodyCannotHoldWhereTheDataEnds) {
    // 10 million vertices (under the vertex limit) but only 12 body bytes: fails at the end of the data, quickly.
    Bytes b;
    b.f32(0).f32(0).f32(0);
    const std::string header = binary_header(10000000, 0);
    const Failure bin = parse_failure(header + b.data);
    EXPECT_TRUE(bin.thrown);
    EXPECT_EQ(bin.line, 0);
    EXPECT_TRUE(contains(bin.what, "truncated body"));
    EXPECT_TRUE(contains(bin.what, "vertex 1 (0-based) of 10000000"));
    EXPECT_TRUE(contains(bin.what, "byte offset " + std::to_string(header.size() + 12)));

    const std::string edge_header =
        "ply\nformat binary_little_endian 1.0\nelement vertex 0\nproperty float x\nproperty float y\n"
        "property float z\nelement edge 18446744073709551615\nproperty list uint double a\nend_header\n";
    Bytes e;
    e.put(uint32_t{0xffffffff});  // a list of 4 billion doubles in a 4-byte body
    const Failure edges = parse_failure(edge_header + e.data);
    EXPECT_TRUE(edges.thrown);
    EXPECT_EQ(edges.line, 0);
    EXPECT_TRUE(contains(edges.what, "truncated body"));
    EXPECT_TRUE(contains(edges.what, "edge 0 (0-based)"));

    const Failure ascii = parse_failure(ascii_triangle(kTriangleVertices, "3 0 1 2\n", 3, 16000000));
    EXPECT_TRUE(ascii.thrown);
    EXPECT_EQ(ascii.line, 14);
    EXPECT_TRUE(contains(ascii.what, "truncated body"));
    EXPECT_TRUE(contains(ascii.what, "face 1 (0-based) of 16000000"));
}

TEST(PlyLoader, rejectsNonNumericToken) {
    const Failure f = parse_failure(ascii_triangle("0 0 0\n1 zero 0\n0 1 0\n"));
    EXPECT_TRUE(f.thrown);
    EXPECT_EQ(f.line, 11);
    EXPECT_TRUE(contains(f.what, "test.ply:11:3:"));
    EXPECT_TRUE(contains(f.what, "'zero'"));

    const Failure fractional_index = parse_failure(ascii_triangle(kTriangleVertices, "3 0 1.5 2\n"));
    EXPECT_TRUE(fractional_index.thrown);
    EXPECT_EQ(fractional_index.line, 13);
    EXPECT_TRUE(contains(fractional_index.what, "'1.5'"));

    const Failure uchar_range = parse_failure(ascii_triangle(kTriangleVertices, "256 0 1 2\n"));
    EXPECT_TRUE(uchar_range.thrown);
    EXPECT_EQ(uchar_range.line, 13);
    EXPECT_TRUE(contains(uchar_range.what, "out of range for type uchar"));
}

TEST(PlyLoader, rejectsExtraTokensOnAsciiLine) {
    const Failure vertex = parse_failure(ascii_triangle("0 0 0\n1 0 0 7\n0 1 0\n"));
    EXPECT_TRUE(vertex.thrown);
    EXPECT_EQ(vertex.line, 11);
    EXPECT_TRUE(contains(vertex.what, "extra tokens"));

    const Failure face = parse_failure(ascii_triangle(kTriangleVertices, "3 0 1 2 0\n"));
    EXPECT_TRUE(face.thrown);
    EXPECT_EQ(face.line, 13);
    EXPECT_TRUE(contains(face.what, "extra tokens"));
}

TEST(PlyLoader, rejectsDataAfterTheLastElement) {
    const Failure ascii = parse_failure(ascii_triangle(kTriangleVertices, "3 0 1 2\n\n3 0 1 2\n"));
    EXPECT_TRUE(ascii.thrown);
    EXPECT_EQ(ascii.line, 15);
    EXPECT_TRUE(contains(ascii.what, "after the last element"));

    Bytes b;
    b.f32(0).f32(0).f32(0).f32(1).f32(0).f32(0).f32(0).f32(1).f32(0).u8(3).i32(0).i32(1).i32(2).u8(9);
    const Failure binary = parse_failure(binary_header(3, 1) + b.data);
    EXPECT_TRUE(binary.thrown);
    EXPECT_EQ(binary.line, 0);
    EXPECT_TRUE(contains(binary.what, "1 unexpected bytes after the last element"));
}

TEST(PlyLoader, rejectsIndexOutOfRangeNamingFaceAndIndex) {
    const Failure ascii = parse_failure(ascii_triangle(kTriangleVertices, "3 0 1 2\n3 2 3 1\n", 3, 2));
    EXPECT_TRUE(ascii.thrown);
    EXPECT_EQ(ascii.line, 14);
    EXPECT_TRUE(contains(ascii.what, "face 1"));
    EXPECT_TRUE(contains(ascii.what, "vertex index 3 out of range"));

    const Failure negative = parse_failure(ascii_triangle(kTriangleVertices, "3 0 -1 2\n"));
    EXPECT_TRUE(negative.thrown);
    EXPECT_EQ(negative.line, 13);
    EXPECT_TRUE(contains(negative.what, "face 0"));
    EXPECT_TRUE(contains(negative.what, "vertex index -1 out of range"));

    Bytes b;
    b.f32(0).f32(0).f32(0).f32(1).f32(0).f32(0).f32(0).f32(1).f32(0).u8(3).i32(0).i32(7).i32(2);
    const std::string header = binary_header(3, 1);
    const Failure binary = parse_failure(header + b.data);
    EXPECT_TRUE(binary.thrown);
    EXPECT_EQ(binary.line, 0);
    EXPECT_TRUE(contains(binary.what, "face 0"));
    EXPECT_TRUE(contains(binary.what, "vertex index 7 out of range"));
    EXPECT_TRUE(contains(binary.what, "byte offset " + std::to_string(header.size() + 36 + 1 + 4)));
}

TEST(PlyLoader, rejectsNegativeCounts) {
    const Failure element = parse_failure("ply\nformat ascii 1.0\nelement vertex -3\nproperty float x\nend_header\n");
    EXPECT_TRUE(element.thrown);
    EXPECT_EQ(element.line, 3);
    EXPECT_TRUE(contains(element.what, "negative count"));

    const Failure ascii_list = parse_failure(
        "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\n"
        "property list int float extra\nend_header\n0 0 0 -2\n");
    EXPECT_TRUE(ascii_list.thrown);
    EXPECT_EQ(ascii_list.line, 9);
    EXPECT_TRUE(contains(ascii_list.what, "negative list count -2"));

    std::string text =
        "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
        "property float z\nelement face 1\nproperty list char int vertex_indices\nend_header\n";
    Bytes b;
    b.f32(0).f32(0).f32(0).f32(1).f32(0).f32(0).f32(0).f32(1).f32(0).put(int8_t{-1}).i32(0).i32(1).i32(2);
    const Failure binary = parse_failure(text + b.data);
    EXPECT_TRUE(binary.thrown);
    EXPECT_EQ(binary.line, 0);
    EXPECT_TRUE(contains(binary.what, "negative list count -1"));
    EXPECT_TRUE(contains(binary.what, "byte offset " + std::to_string(text.size() + 36)));
}

TEST(PlyLoader, rejectsPolygonsWithTooManyOrTooFewVertices) {
    std::string big = "1025";
    for (int i = 0; i < 1025; ++i) big += " 0";
    const Failure many = parse_failure(
        "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\n"
        "element face 1\nproperty list ushort int vertex_indices\nend_header\n0 0 0\n" + big + "\n");
    EXPECT_TRUE(many.thrown);
    EXPECT_EQ(many.line, 11);
    EXPECT_TRUE(contains(many.what, "1025 vertices (limit 1024)"));

    const Failure few = parse_failure(ascii_triangle(kTriangleVertices, "2 0 1\n"));
    EXPECT_TRUE(few.thrown);
    EXPECT_EQ(few.line, 13);
    EXPECT_TRUE(contains(few.what, "face 0 (0-based) has 2 vertices"));
}

TEST(PlyLoader, rejectsVertexAndFaceCountsOverLimitsFromTheHeader) {
    // 4 billion vertices: must fail on the header line, without allocating or reading a body.
    const Failure vertices = parse_failure(
        "ply\nformat binary_little_endian 1.0\nelement vertex 4000000000\nproperty float x\nproperty float y\n"
        "property float z\nend_header\n");
    EXPECT_TRUE(vertices.thrown);
    EXPECT_EQ(vertices.line, 3);
    EXPECT_TRUE(contains(vertices.what, "too many vertices: 4000000000"));

    const Failure faces = parse_failure(ascii_triangle(kTriangleVertices, "3 0 1 2\n", 3, (1 << 24) + 1));
    EXPECT_TRUE(faces.thrown);
    EXPECT_EQ(faces.line, 7);
    EXPECT_TRUE(contains(faces.what, "too many faces"));

    const Failure huge = parse_failure("ply\nformat ascii 1.0\nelement vertex 99999999999999999999999\nend_header\n");
    EXPECT_TRUE(huge.thrown);
    EXPECT_EQ(huge.line, 3);
    EXPECT_TRUE(contains(huge.what, "too large"));
}

TEST(PlyLoader, rejectsNonFiniteCoordinates) {
    for (const std::string token : {"nan", "inf", "-inf", "1e39"}) {
        const Failure f = parse_failure(ascii_triangle("0 0 0\n1 " + token + " 0\n0 1 0\n"));
        EXPECT_TRUE(f.thrown) << token;
        EXPECT_EQ(f.line, 11) << token;
        EXPECT_TRUE(contains(f.what, "y coordinate")) << token;
    }
    const Failure overflow = parse_failure(ascii_triangle("0 0 0\n1 0 1e999\n0 1 0\n"));
    EXPECT_TRUE(overflow.thrown);
    EXPECT_EQ(overflow.line, 11);
    EXPECT_TRUE(contains(overflow.what, "out of range"));

    Bytes b;
    b.f32(0).f32(0).f32(0).f32(1).f32(std::numeric_limits<float>::quiet_NaN()).f32(0).f32(0).f32(1).f32(0);
    b.u8(3).i32(0).i32(1).i32(2);
    const std::string header = binary_header(3, 1);
    const Failure binary = parse_failure(header + b.data);
    EXPECT_TRUE(binary.thrown);
    EXPECT_EQ(binary.line, 0);
    EXPECT_TRUE(contains(binary.what, "non-finite y coordinate"));
    EXPECT_TRUE(contains(binary.what, "byte offset " + std::to_string(header.size() + 16)));
}

TEST(PlyLoader, rejectsPartialColourAndUnsupportedColourType) {
    const Failure partial = parse_failure(
        "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\n"
        "property uchar red\nproperty uchar green\nend_header\n0 0 0 1 1\n");
    EXPECT_TRUE(partial.thrown);
    EXPECT_EQ(partial.line, 3);
    EXPECT_TRUE(contains(partial.what, "red, green, blue"));

    const Failure type = parse_failure(
        "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\n"
        "property int red\nproperty int green\nproperty int blue\nend_header\n0 0 0 1 1 1\n");
    EXPECT_TRUE(type.thrown);
    EXPECT_EQ(type.line, 7);
    EXPECT_TRUE(contains(type.what, "unsupported colour type int"));
}

}  // namespace
