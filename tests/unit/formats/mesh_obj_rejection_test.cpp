// OBJ loader rejections, one table: each input is refused with an InputError naming the file, the line and the
// problem, including the refusals (and the wording) kept from tinyobjloader, which raster read OBJ files with before.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "raster/core/errors.h"
#include "raster/formats/mesh_obj.h"

namespace {

using raster::InputError;
using raster::parse_obj;

struct Rejection {
    const char* name;
    std::string text;
    int line;             // 0: the file as a whole
    std::string problem;  // a part of the message
};

const std::string kTriangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";  // lines 1 to 3

// `corners` vertices and, on the line after them, one face through all of them.
std::string face_of(int corners) {
    std::string text, face = "f";
    for (int i = 1; i <= corners; ++i) {
        const std::string index = std::to_string(i);
        text += "v " + index + " 0 0\n";
        face += ' ' + index;
    }
    return text + face + "\n";
}

std::vector<Rejection> rejections() {
    return {
        // Indices the file does not have.
        {"vertexIndexPastTheEnd", kTriangle + "f 1 2 4\n", 4, "4"},
        {"vertexIndexZero", kTriangle + "f 0 1 2\n", 4, "0"},  // OBJ counts from 1
        {"relativeIndexBeforeTheFirstVertex", kTriangle + "f -4 -2 -1\n", 4, "-4"},  // only 3 precede the face
        {"normalIndexPastTheEnd", kTriangle + "vn 0 0 1\nf 1//1 2//2 3//1\n", 5, "normal"},
        {"relativeNormalIndexBeforeTheFirstNormal", kTriangle + "vn 0 0 1\nf 1//-2 2//1 3//1\n", 5,
         "relative index -2 but only 1 normals precede it"},
        {"indexOutOfTheLongRange", kTriangle + "f 1 2 99999999999999999999\n", 4, "99999999999999999999"},
        {"forwardReferenceNeverDefined", "f 1 2 5\n" + kTriangle, 1, "face uses vertex 5 but the file has 3"},
        // Coordinates that are not finite numbers.
        {"vertexNan", "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n", 2, "nan"},
        {"vertexMinusInfinity", "v 0 0 0\nv 1 0 0\nv 0 1 -inf\nf 1 2 3\n", 3, "inf"},
        {"vertexOverflow", "v 0 0 0\nv 1 0 1e999\nv 0 1 0\nf 1 2 3\n", 2, "1e999"},
        {"normalNan", kTriangle + "vn 0 NaN 1\nf 1//1 2//1 3//1\n", 4, "NaN"},
        {"vertexWord", "v 0 0 0\nv one 0 0\nv 0 1 0\nf 1 2 3\n", 2, "one"},
        // tinyobjloader's arithmetic makes 0 * 5^500 not a number; its check came after every line's.
        {"vertexZeroWithAHugeExponent", "v 0e500 0 0\n" + kTriangle + "f 2 3 4\n", 0,
         "a vertex coordinate is not a finite number"},
        {"usedNormalZeroWithAHugeExponent", kTriangle + "vn 0 0e500 1\nf 1//1 2//1 3//1\n", 0,
         "a normal is not a finite number"},
        // Truncated statements.
        {"vertexCutShort", "v 0 0 0\nv 1 0 0\nv 0 1", 3, "3 coordinates"},
        {"faceCutShort", kTriangle + "f 1 2", 4, "3 vertices"},
        {"normalCutShort", kTriangle + "vn 0 0\nf 1 2 3\n", 4, "3 coordinates"},
        // Not OBJ text at all.
        {"prose", "hello world\nthis is not an OBJ file\n", 1, "hello"},
        {"htmlAfterTheMesh", kTriangle + "f 1 2 3\n<html><body>404</body></html>\n", 5, "html"},
        {"pngBytes", std::string("\x89PNG\r\n\x1a\n\0\0\0\rIHDR", 16), 1, "not an OBJ statement: '?PNG'"},
        // Face corners that are not v, v/vt, v//vn or v/vt/vn.
        {"cornerOfFourParts", kTriangle + "f 1/1/1/1 2 3\n", 4, "face corner '1/1/1/1' has more than 3 parts"},
        {"cornerWithAnEmptyNormal", kTriangle + "f 1/1/ 2 3\n", 4, "face corner '1/1/' has an empty normal index"},
        {"cornerThatIsNoIndex", kTriangle + "f 1 2 x3\n", 4, "face corner 'x3' is not a vertex index"},
        // The limit on corners per face (docs: polygons of at most 1,024 vertices).
        {"faceOverThePolygonLimit", face_of(1025), 1026, "more than 1024"},
        // Refused by tinyobjloader, in its words, with its line in them: a texture index that reads as 0 (an
        // empty one at the end of the line too), an `l` or `p` corner that does, a negative `vw` joint id.
        {"textureIndexZero", kTriangle + "vt 0 0\nf 1/0 2/1 3/1\n", 5,
         "Failed parse `f' line(e.g. zero value for face index. line 5.)"},
        {"emptyTextureIndexAtTheEnd", kTriangle + "f 1 2 3/\n", 4,
         "Failed parse `f' line(e.g. zero value for face index. line 4.)"},
        {"lineCornerZero", kTriangle + "l 1 0\n", 4,
         "Failed parse `l' line(e.g. zero value for vertex index. line 4.)"},
        {"pointCornerWord", kTriangle + "p x\n", 4, "Failed parse `p' line(e.g. zero value for vertex index. line 4.)"},
        {"lineOfBlanksOnly", kTriangle + "l  \n", 4, "Failed parse `l' line(e.g. zero value for vertex index."},
        {"negativeJointId", kTriangle + "vw 1 -1 0.5\n", 4, "Failed parse `vw' line. joint_id is negative. line 4.)"},
        {"jointIdThatIsNoNumber", kTriangle + "vw 1 x 0.5\n", 4, "Failed parse `vw' line. joint_id is negative."},
        // tinyobjloader counted a lone carriage return as a line break: line 1 is two lines to it.
        {"tinyobjloaderLineCountAfterACarriageReturn", "# one\rtwo\n" + kTriangle + "l 0\n", 6,
         "Failed parse `l' line(e.g. zero value for vertex index. line 6.)"},
        // Which error wins: every line check comes first, then the forward references, then tinyobjloader's.
        {"lineCheckBeforeTinyobjloader", kTriangle + "l 0\nhello\n", 5, "not an OBJ statement: 'hello'"},
        {"forwardReferenceBeforeTinyobjloader", kTriangle + "l 0\nf 1 2 9\n", 5, "face uses vertex 9"},
    };
}

class ObjRejection : public testing::TestWithParam<Rejection> {};

TEST_P(ObjRejection, isAnInputErrorNamingFileLineAndProblem) {
    const Rejection& r = GetParam();
    try {
        parse_obj(r.text, "model.obj");
        ADD_FAILURE() << "accepted: " << r.text;
    } catch (const InputError& e) {
        EXPECT_EQ(e.file(), "model.obj");
        EXPECT_EQ(e.line(), r.line) << e.message();
        EXPECT_NE(e.message().find(r.problem), std::string::npos) << e.message() << " lacks " << r.problem;
    }
}

INSTANTIATE_TEST_SUITE_P(ObjLoader, ObjRejection, testing::ValuesIn(rejections()),
                         [](const testing::TestParamInfo<Rejection>& info) { return std::string(info.param.name); });

}  // namespace
