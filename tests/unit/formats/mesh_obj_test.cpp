// OBJ loader tests: objects, normals, vertex colours, polygon triangulation, relative indices, and rejected input.
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "raster/core/errors.h"
#include "raster/formats/mesh_obj.h"

namespace {

using raster::InputError;
using raster::MeshData;
using raster::parse_obj;

// What parse_obj threw for input that must be rejected.
struct Failure {
    bool thrown = false;
    std::string file;
    int line = -1;
    std::string message;
};

Failure obj_failure(const std::string& text) {
    Failure f;
    try {
        parse_obj(text, "model.obj");
    } catch (const InputError& e) {
        f.thrown = true;
        f.file = e.file();
        f.line = e.line();
        f.message = e.message();
    }
    return f;
}

testing::AssertionResult contains(const std::string& text, const std::string& part) {
    if (text.find(part) != std::string::npos) return testing::AssertionSuccess();
    return testing::AssertionFailure() << "'" << text << "' does not contain '" << part << "'";
}

void expect_rejected(const std::string& text, int line, const std::string& problem) {
    const Failure f = obj_failure(text);
    ASSERT_TRUE(f.thrown) << "accepted: " << text;
    EXPECT_EQ(f.file, "model.obj");
    EXPECT_EQ(f.line, line) << f.message;
    EXPECT_TRUE(contains(f.message, problem));
}

void expect_vec3(const glm::vec3& v, float x, float y, float z) {
    EXPECT_FLOAT_EQ(v.x, x);
    EXPECT_FLOAT_EQ(v.y, y);
    EXPECT_FLOAT_EQ(v.z, z);
}

// The triangle's corners as positions, so tests do not depend on how vertices are numbered.
std::vector<glm::vec3> corners(const MeshData& mesh, size_t triangle) {
    const auto& t = mesh.triangles.at(triangle);
    return {mesh.positions.at(t.v[0]), mesh.positions.at(t.v[1]), mesh.positions.at(t.v[2])};
}

void expect_triangle(const MeshData& mesh, size_t triangle, glm::vec3 a, glm::vec3 b, glm::vec3 c) {
    const std::vector<glm::vec3> p = corners(mesh, triangle);
    expect_vec3(p[0], a.x, a.y, a.z);
    expect_vec3(p[1], b.x, b.y, b.z);
    expect_vec3(p[2], c.x, c.y, c.z);
}

const std::string kSquare = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";

TEST(ObjLoader, keepsEveryObjectWithNameAndFirstTriangle) {
    const MeshData mesh = parse_obj("o first\n"
                                    "v 0 0 0\nv 1 0 0\nv 0 1 0\n"
                                    "f 1 2 3\n"
                                    "o second\n"
                                    "v 0 0 1\nv 1 0 1\nv 0 1 1\nv 1 1 1\n"
                                    "f 4 5 6\n"
                                    "f 5 7 6\n"
                                    "o third\n"
                                    "f 1 3 7\n",
                                    "model.obj");
    ASSERT_EQ(mesh.triangles.size(), 4u);
    ASSERT_EQ(mesh.object_names.size(), 3u);
    EXPECT_EQ(mesh.object_names[0], "first");
    EXPECT_EQ(mesh.object_names[1], "second");
    EXPECT_EQ(mesh.object_names[2], "third");
    ASSERT_EQ(mesh.object_first_triangle.size(), 3u);
    EXPECT_EQ(mesh.object_first_triangle[0], 0u);
    EXPECT_EQ(mesh.object_first_triangle[1], 1u);
    EXPECT_EQ(mesh.object_first_triangle[2], 3u);
    expect_triangle(mesh, 0, {0, 0, 0}, {1, 0, 0}, {0, 1, 0});
    expect_triangle(mesh, 1, {0, 0, 1}, {1, 0, 1}, {0, 1, 1});
    expect_triangle(mesh, 2, {1, 0, 1}, {1, 1, 1}, {0, 1, 1});
    expect_triangle(mesh, 3, {0, 0, 0}, {0, 1, 0}, {1, 1, 1});
}

TEST(ObjLoader, groupsAlsoStartObjects) {
    const MeshData mesh = parse_obj(kSquare + "g left\nf 1 2 3\ng right\nf 1 3 4\n", "model.obj");
    ASSERT_EQ(mesh.object_names.size(), 2u);
    EXPECT_EQ(mesh.object_names[0], "left");
    EXPECT_EQ(mesh.object_names[1], "right");
    EXPECT_EQ(mesh.object_first_triangle.at(1), 1u);
    expect_triangle(mesh, 1, {0, 0, 0}, {1, 1, 0}, {0, 1, 0});
}

TEST(ObjLoader, keepsNormalsWhenEveryCornerHasOne) {
    // Two triangles share the edge (2, 3) but with different normals there: those corners become separate vertices.
    const MeshData mesh = parse_obj(kSquare +
                                        "vn 0 0 1\nvn 0 1 0\n"
                                        "f 1//1 2//1 4//1\n"
                                        "f 2//2 3//2 4//2\n",
                                    "model.obj");
    ASSERT_EQ(mesh.triangles.size(), 2u);
    EXPECT_EQ(mesh.positions.size(), 6u);  // (1,n1) (2,n1) (4,n1) (2,n2) (3,n2) (4,n2)
    ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
    expect_triangle(mesh, 0, {0, 0, 0}, {1, 0, 0}, {0, 1, 0});
    expect_triangle(mesh, 1, {1, 0, 0}, {1, 1, 0}, {0, 1, 0});
    for (int k = 0; k < 3; ++k) {
        const glm::vec3 n0 = mesh.normals.at(mesh.triangles[0].v[k]);
        const glm::vec3 n1 = mesh.normals.at(mesh.triangles[1].v[k]);
        expect_vec3(n0, 0, 0, 1);
        expect_vec3(n1, 0, 1, 0);
    }
    // The shared position 2 is two different vertices, one per normal.
    EXPECT_NE(mesh.triangles[0].v[1], mesh.triangles[1].v[0]);
}

TEST(ObjLoader, sharesVerticesWithTheSamePositionAndNormal) {
    const MeshData mesh = parse_obj(kSquare + "vn 0 0 1\nf 1//1 2//1 3//1\nf 1//1 3//1 4//1\n", "model.obj");
    EXPECT_EQ(mesh.positions.size(), 4u);
    ASSERT_EQ(mesh.normals.size(), 4u);
    EXPECT_EQ(mesh.triangles.at(0).v[0], mesh.triangles.at(1).v[0]);
    EXPECT_EQ(mesh.triangles.at(0).v[2], mesh.triangles.at(1).v[1]);
    // v/vt/vn corners carry normals too; texture coordinates are not read.
    const MeshData textured = parse_obj(kSquare + "vt 0 0\nvt 1 0\nvn 0 0 1\nf 1/1/1 2/2/1 3/1/1\n", "model.obj");
    EXPECT_EQ(textured.normals.size(), 3u);
}

TEST(ObjLoader, dropsNormalsWhenSomeCornerLacksOne) {
    const MeshData mesh = parse_obj(kSquare + "vn 0 0 1\nf 1//1 2//1 3//1\nf 1 3 4\n", "model.obj");
    EXPECT_TRUE(mesh.normals.empty());
    EXPECT_EQ(mesh.positions.size(), 4u);  // positions keep their file numbering
    ASSERT_EQ(mesh.triangles.size(), 2u);
    EXPECT_EQ(mesh.triangles[0].v[0], 0u);
    EXPECT_EQ(mesh.triangles[1].v[2], 3u);
    // One face corner without its normal is enough.
    EXPECT_TRUE(parse_obj(kSquare + "vn 0 0 1\nf 1//1 2 3//1\n", "model.obj").normals.empty());
}

TEST(ObjLoader, keepsVertexColoursOnlyWhenEveryVertexHasThem) {
    const MeshData coloured = parse_obj("v 0 0 0 1 0 0\nv 1 0 0 0 1 0\nv 0 1 0 0 0 1\nf 1 2 3\n", "model.obj");
    ASSERT_EQ(coloured.colors.size(), 3u);
    expect_vec3(coloured.colors[0], 1, 0, 0);
    expect_vec3(coloured.colors[1], 0, 1, 0);
    expect_vec3(coloured.colors[2], 0, 0, 1);
    expect_vec3(coloured.positions[1], 1, 0, 0);  // colours are not mistaken for coordinates

    const MeshData partly = parse_obj("v 0 0 0 1 0 0\nv 1 0 0\nv 0 1 0 0 0 1\nf 1 2 3\n", "model.obj");
    EXPECT_TRUE(partly.colors.empty());
    EXPECT_EQ(partly.triangles.size(), 1u);

    // Colours survive the split of vertices by normal.
    const MeshData with_normals =
        parse_obj("v 0 0 0 1 0 0\nv 1 0 0 0 1 0\nv 0 1 0 0 0 1\nvn 0 0 1\nf 1//1 2//1 3//1\n", "model.obj");
    ASSERT_EQ(with_normals.colors.size(), with_normals.positions.size());
    expect_vec3(with_normals.colors.at(with_normals.triangles.at(0).v[1]), 0, 1, 0);
}

// Signed area in the z = 0 plane (counter-clockwise positive).
float signed_area(const MeshData& mesh, size_t triangle) {
    const std::vector<glm::vec3> p = corners(mesh, triangle);
    return 0.5f * ((p[1].x - p[0].x) * (p[2].y - p[0].y) - (p[2].x - p[0].x) * (p[1].y - p[0].y));
}

// A convex polygon of n corners becomes n - 2 triangles of its own corners, with its winding, tiling its area.
void expect_triangulated(const MeshData& mesh, size_t corners_in_polygon, float polygon_area) {
    ASSERT_EQ(mesh.triangles.size(), corners_in_polygon - 2);
    float total = 0.0f;
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        for (uint32_t v : mesh.triangles[t].v) EXPECT_LT(v, corners_in_polygon);
        EXPECT_GT(signed_area(mesh, t), 0.0f) << "triangle " << t << " lost the polygon's winding";
        total += signed_area(mesh, t);
    }
    EXPECT_NEAR(total, polygon_area, 1e-5f);
}

TEST(ObjLoader, triangulatesQuadsAndPentagons) {
    const MeshData quad = parse_obj(kSquare + "f 1 2 3 4\n", "model.obj");
    expect_triangulated(quad, 4, 1.0f);

    // Shoelace area of (0,0) (2,0) (3,1) (1,3) (-1,1): (0 + 2 + 8 + 4 + 0) / 2 = 7.
    const MeshData pentagon =
        parse_obj("v 0 0 0\nv 2 0 0\nv 3 1 0\nv 1 3 0\nv -1 1 0\nf 1 2 3 4 5\n", "model.obj");
    expect_triangulated(pentagon, 5, 7.0f);

    // A quad followed by a triangle: 2 + 1 triangles, the triangle unchanged and last.
    const MeshData mixed = parse_obj(kSquare + "v 5 5 0\nf 1 2 3 4\nf 2 5 3\n", "model.obj");
    ASSERT_EQ(mixed.triangles.size(), 3u);
    expect_triangle(mixed, 2, {1, 0, 0}, {5, 5, 0}, {1, 1, 0});
}

TEST(ObjLoader, resolvesNegativeIndicesRelativeToPrecedingVertices) {
    // -1 is the last vertex defined so far.
    const MeshData mesh = parse_obj("v 0 0 0\nv 1 0 0\nv 0 1 0\n"
                                    "f -3 -2 -1\n"
                                    "v 1 1 0\n"
                                    "f -4 -2 -1\n",
                                    "model.obj");
    ASSERT_EQ(mesh.triangles.size(), 2u);
    expect_triangle(mesh, 0, {0, 0, 0}, {1, 0, 0}, {0, 1, 0});
    expect_triangle(mesh, 1, {0, 0, 0}, {0, 1, 0}, {1, 1, 0});
    // Relative normal indices too.
    const MeshData normals = parse_obj(kSquare + "vn 1 0 0\nvn 0 0 1\nf -4//-1 -3//-1 -2//-2\n", "model.obj");
    ASSERT_EQ(normals.normals.size(), 3u);
    expect_vec3(normals.normals.at(normals.triangles.at(0).v[0]), 0, 0, 1);
    expect_vec3(normals.normals.at(normals.triangles.at(0).v[2]), 1, 0, 0);
}

TEST(ObjLoader, rejectsIndicesOutOfRange) {
    const std::string triangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    expect_rejected(triangle + "f 1 2 4\n", 4, "4");
    expect_rejected(triangle + "f 0 1 2\n", 4, "0");              // OBJ counts from 1
    expect_rejected(triangle + "f -4 -2 -1\n", 4, "-4");          // only 3 vertices precede the face
    expect_rejected(triangle + "vn 0 0 1\nf 1//1 2//2 3//1\n", 5, "normal");
    expect_rejected(triangle + "f 1 2 99999999999999999999\n", 4, "99999999999999999999");
}

TEST(ObjLoader, rejectsNonFiniteCoordinates) {
    expect_rejected("v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n", 2, "nan");
    expect_rejected("v 0 0 0\nv 1 0 0\nv 0 1 -inf\nf 1 2 3\n", 3, "inf");
    expect_rejected("v 0 0 0\nv 1 0 1e999\nv 0 1 0\nf 1 2 3\n", 2, "1e999");
    expect_rejected("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 NaN 1\nf 1//1 2//1 3//1\n", 4, "NaN");
    // Not numbers at all.
    expect_rejected("v 0 0 0\nv one 0 0\nv 0 1 0\nf 1 2 3\n", 2, "one");
}

TEST(ObjLoader, rejectsTruncatedStatements) {
    expect_rejected("v 0 0 0\nv 1 0 0\nv 0 1", 3, "3 coordinates");
    expect_rejected("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2", 4, "3 vertices");
    expect_rejected("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0\nf 1 2 3\n", 4, "3 coordinates");
}

TEST(ObjLoader, rejectsGarbageText) {
    expect_rejected("hello world\nthis is not an OBJ file\n", 1, "hello");
    expect_rejected("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n<html><body>404</body></html>\n", 5, "html");
    const Failure binary = obj_failure(std::string("\x89PNG\r\n\x1a\n\0\0\0\rIHDR", 16));
    EXPECT_TRUE(binary.thrown);
    EXPECT_EQ(binary.line, 1);
}

TEST(ObjLoader, rejectsPolygonsOverTheLimit) {
    // README: polygons of at most 1,024 vertices.
    std::string text;
    for (int i = 0; i < 1025; ++i) {  // corners on a circle: a convex polygon
        const double angle = 2.0 * M_PI * i / 1025.0;
        text += "v ";
        text += std::to_string(std::cos(angle));
        text += ' ';
        text += std::to_string(std::sin(angle));
        text += " 0\n";
    }
    std::string face = "f";
    for (int i = 1; i <= 1024; ++i) {
        face += ' ';
        face += std::to_string(i);
    }
    EXPECT_EQ(parse_obj(text + face + "\n", "model.obj").triangles.size(), 1022u);
    face += " 1025\n";
    expect_rejected(text + face, 1026, "1024");
}

TEST(ObjLoader, acceptsOrdinaryObjStatementsItDoesNotUse) {
    const MeshData mesh = parse_obj("# exported\r\n"
                                    "mtllib scene.mtl\r\n"
                                    "o thing\r\n"
                                    "v 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\n"
                                    "vt 0 0\r\nvt 1 0\r\nvt 0 1\r\n"
                                    "usemtl red\r\n"
                                    "s off\r\n"
                                    "f 1/1 2/2 3/3\r\n"
                                    "l 1 2\r\n",
                                    "model.obj");
    ASSERT_EQ(mesh.triangles.size(), 1u);
    expect_triangle(mesh, 0, {0, 0, 0}, {1, 0, 0}, {0, 1, 0});
    EXPECT_TRUE(mesh.normals.empty());
    EXPECT_EQ(mesh.object_names.at(0), "thing");
}

TEST(ObjLoader, neverCrashesOnMangledInput) {
    // Random edits of a valid file: every outcome is a mesh whose indices are in range, or an InputError.
    const std::string valid = "o a\nv 0 0 0\nv 1 0 0\nv 1 1 0 0.5 0.5 0.5\nv 0 1 0\nvn 0 0 1\nvt 0 0\n"
                              "f 1//1 2//1 3//1\nf 1 3 4\ng b\nf -1 -2 -3 -4\n";
    const char kAlphabet[] = "0123456789 -+./\n#vfnoge\0\xff";
    const std::string alphabet(kAlphabet, sizeof kAlphabet - 1);
    std::mt19937 random(12345);
    int accepted = 0, rejected = 0;
    for (int round = 0; round < 400; ++round) {
        std::string text = valid;
        const int edits = 1 + static_cast<int>(random() % 6);
        for (int e = 0; e < edits; ++e) {
            const size_t at = random() % (text.size() + 1);
            switch (random() % 3) {
                case 0: text.insert(at, 1, alphabet[random() % alphabet.size()]); break;
                case 1: if (at < text.size()) text.erase(at, 1); break;
                default: text.resize(at); break;  // truncation
            }
        }
        try {
            const MeshData mesh = parse_obj(text, "model.obj");
            ++accepted;
            for (const auto& t : mesh.triangles)
                for (uint32_t v : t.v) ASSERT_LT(v, mesh.positions.size()) << text;
            EXPECT_TRUE(mesh.normals.empty() || mesh.normals.size() == mesh.positions.size());
            EXPECT_TRUE(mesh.colors.empty() || mesh.colors.size() == mesh.positions.size());
        } catch (const InputError&) {
            ++rejected;
        }
    }
    EXPECT_GT(accepted, 0);
    EXPECT_GT(rejected, 0);
}

}  // namespace
