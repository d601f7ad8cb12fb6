// OBJ loader tests on input it accepts: objects, normals, vertex colours, triangulation, relative indices, and the
// ways of tinyobjloader (which raster read OBJ files with before) that the reader keeps.
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "raster/core/errors.h"
#include "raster/formats/mesh_obj.h"
#include "raster/formats/mesh_obj_reader.h"

namespace {

using raster::InputError;
using raster::MeshData;
using raster::parse_obj;
using namespace std::string_literals;

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

TEST(ObjLoader, resolvesNegativeTextureIndicesRelativeToPrecedingCoordinates) {
    // -1 is the last texture coordinate defined so far, as for positions.
    const std::string text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nf 1/-3 2/-2 3/-1\n"
                             "vt 0.5 0.5\nf 1/-1 2/-4 3/-2\n";
    const raster::obj::ObjStatements statements = raster::obj::read_obj_statements(text, "model.obj");
    ASSERT_EQ(statements.corners.size(), 6u);
    const uint32_t expected[6] = {0, 1, 2, 3, 0, 2};
    for (size_t i = 0; i < 6; ++i) EXPECT_EQ(statements.corners[i].texcoord, expected[i]) << "corner " << i;
}

TEST(ObjLoader, triangulatesAPolygonAtTheLimit) {
    // docs: polygons of at most 1,024 vertices (mesh_obj_rejection_test refuses 1,025).
    std::string text;
    for (int i = 0; i < 1025; ++i) {  // corners on a circle: a convex polygon
        const double angle = 2.0 * M_PI * i / 1025.0;
        text += "v " + std::to_string(std::cos(angle)) + ' ' + std::to_string(std::sin(angle)) + " 0\n";
    }
    std::string face = "f";
    for (int i = 1; i <= 1024; ++i) face += ' ' + std::to_string(i);
    EXPECT_EQ(parse_obj(text + face + "\n", "model.obj").triangles.size(), 1022u);
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

// tinyobjloader's objects: an `o` names the object with the rest of its line, word for word; a `g` with its words
// joined by one space; an `o` or `g` with no blank after it starts nothing.
TEST(ObjLoader, namesObjectsAsTinyobjloaderDid) {
    const MeshData mesh = parse_obj(kSquare + "o  my  thing \nf 1 2 3\ng a\tb   c\nf 1 3 4\ng \nf 2 3 4\n"
                                              "o\nf 1 2 4\ng\nf 1 2 3\n",
                                    "model.obj");
    EXPECT_EQ(mesh.object_names, (std::vector<std::string>{" my  thing ", "a b c", ""}));
    EXPECT_EQ(mesh.object_first_triangle, (std::vector<uint32_t>{0, 1, 2}));
    EXPECT_EQ(mesh.triangles.size(), 5u);  // the last group holds the faces after the bare `o` and `g`
}

TEST(ObjLoader, namesTheFacesBeforeAnyObjectWithTheEmptyName) {
    const MeshData mesh = parse_obj(kSquare + "f 1 2 3\no named\nf 1 3 4\n", "model.obj");
    EXPECT_EQ(mesh.object_names, (std::vector<std::string>{"", "named"}));
    EXPECT_EQ(mesh.object_first_triangle, (std::vector<uint32_t>{0, 1}));
}

// Which objects without triangles are kept: an `o` ends one that has an `l` or `p` corner, a `g` drops it, and
// the end of the file keeps the last one when it has any f, l or p statement.
TEST(ObjLoader, keepsObjectsWithoutTrianglesAsTinyobjloaderDid) {
    const MeshData objects = parse_obj(kSquare + "o empty\no lines\nl 1 2\no points\np 3\no faces\nf 1 2 3\n"
                                                 "o tail\nl 1 2\n",
                                       "model.obj");
    EXPECT_EQ(objects.object_names, (std::vector<std::string>{"lines", "points", "faces", "tail"}));
    EXPECT_EQ(objects.object_first_triangle, (std::vector<uint32_t>{0, 0, 0, 1}));

    const MeshData groups = parse_obj(kSquare + "g empty\ng lines\nl 1 2\ng faces\nf 1 2 3\ng\nl\n", "model.obj");
    EXPECT_EQ(groups.object_names, (std::vector<std::string>{"faces"}));  // a bare `l` is no statement either
    EXPECT_TRUE(parse_obj(kSquare, "model.obj").object_names.empty());
}

// A vertex has a colour when it has three numbers after x y z; 4 numbers (x y z w) are not a colour, and one vertex
// without drops them all.
TEST(ObjLoader, readsColoursFromTheFourthToTheSixthNumber) {
    const MeshData seven = parse_obj("v 0 0 0 1 0.5 0 9\nv 1 0 0 0 1 0 9\nv 0 1 0 0 0 1 9\nf 1 2 3\n", "model.obj");
    ASSERT_EQ(seven.colors.size(), 3u);
    expect_vec3(seven.colors[0], 1, 0.5f, 0);
    EXPECT_TRUE(parse_obj("v 0 0 0 1\nv 1 0 0 1\nv 0 1 0 1\nf 1 2 3\n", "model.obj").colors.empty());
}

// The quad rule (polygon_triangulation_test has the rest): the unit square's diagonals tie and it splits along
// corners 2-4; a quad whose 1-3 diagonal is shorter splits along that one.
TEST(ObjLoader, splitsQuadsAlongTheShorterDiagonal) {
    const MeshData square = parse_obj(kSquare + "f 1 2 3 4\n", "model.obj");
    ASSERT_EQ(square.triangles.size(), 2u);
    expect_triangle(square, 0, {0, 0, 0}, {1, 0, 0}, {0, 1, 0});
    expect_triangle(square, 1, {1, 0, 0}, {1, 1, 0}, {0, 1, 0});
    const MeshData kite = parse_obj("v 0 0 0\nv 1 -2 0\nv 2 0 0\nv 1 2 0\nf 1 2 3 4\n", "model.obj");
    ASSERT_EQ(kite.triangles.size(), 2u);
    expect_triangle(kite, 0, {0, 0, 0}, {1, -2, 0}, {2, 0, 0});
    expect_triangle(kite, 1, {0, 0, 0}, {2, 0, 0}, {1, 2, 0});
}

// Texture indices are checked as tinyobjloader checked them (refused when they read as 0 by atoi: see the
// rejection table) and otherwise ignored: past the end, relative, or empty with the next corner read in its place.
TEST(ObjLoader, ignoresTextureIndicesThatTinyobjloaderRead) {
    const MeshData mesh = parse_obj(kSquare + "vt 0 0\nf 1/9 2/-5 3/1x\nf 1/ 2 4\n", "model.obj");
    ASSERT_EQ(mesh.triangles.size(), 2u);
    expect_triangle(mesh, 1, {0, 0, 0}, {1, 0, 0}, {0, 1, 0});
}

// tinyobjloader read a line as a C string, up to its first NUL byte: so does the reader (the checks still cover
// the whole line): "name" is the object's name and the face has the corners before the NUL.
TEST(ObjLoader, readsALineUpToItsFirstNulByte) {
    const MeshData mesh = parse_obj(kSquare + "o name\0 more\nf 1 2 3\0 4\n"s, "model.obj");
    EXPECT_EQ(mesh.object_names, std::vector<std::string>{"name"});
    ASSERT_EQ(mesh.triangles.size(), 1u);
    expect_triangle(mesh, 0, {0, 0, 0}, {1, 0, 0}, {1, 1, 0});
}

// A carriage return that does not end the line ends the statement, as it did for tinyobjloader; but to
// tinyobjloader it also began a line of its own, which no check had seen ("# note\rv 5 5 5" added a vertex), and
// the reader reads no statement there.
TEST(ObjLoader, readsNoStatementAfterACarriageReturnInsideALine) {
    const MeshData mesh = parse_obj(kSquare + "o a\rb\n# note\rv 5 5 5\nf 1 2 3\n", "model.obj");
    EXPECT_EQ(mesh.object_names, std::vector<std::string>{"a"});
    EXPECT_EQ(mesh.positions.size(), 4u);
}

// Unlike tinyobjloader, which dropped a quad whose corner was defined only after the quad's object ended, every
// face whose corners the file defines is kept.
TEST(ObjLoader, keepsAQuadWhoseCornerIsDefinedAfterItsObject) {
    const MeshData mesh = parse_obj("o first\nv 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3 4\no second\nv 0 1 0\n",
                                    "model.obj");
    EXPECT_EQ(mesh.object_names, std::vector<std::string>{"first"});
    EXPECT_EQ(mesh.triangles.size(), 2u);
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
