// PLY loader rejections, one table: header, ascii body and binary body errors, each an InputError at its line
// (column too where a token is at fault; binary errors are on line 0 and name the byte offset instead).
#include <bit>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "raster/core/errors.h"
#include "raster/formats/mesh_ply.h"

namespace {

using raster::InputError;
using raster::parse_ply;

struct Rejection {
    const char* name;
    std::string bytes;
    int line;                        // 0 for binary body errors
    std::vector<std::string> parts;  // each a part of what() ("test.ply:line:column: message")
};

// A tiny ascii file: one triangle after the given vertex lines (line 10 is the first vertex, 13 the face).
std::string ascii_triangle(const std::string& vertex_lines, const std::string& face_lines = "3 0 1 2\n",
                           int vertices = 3, int faces = 1) {
    return "ply\nformat ascii 1.0\nelement vertex " + std::to_string(vertices) +
           "\nproperty float x\nproperty float y\nproperty float z\nelement face " + std::to_string(faces) +
           "\nproperty list uchar int vertex_indices\nend_header\n" + vertex_lines + face_lines;
}

const std::string kTriangleVertices = "0 0 0\n1 0 0\n0 1 0\n";

// `values` as a binary_little_endian body holds them, written in host order on the little-endian hosts we run on.
template <class... T>
std::string little_endian(T... values) {
    static_assert(std::endian::native == std::endian::little);
    std::string bytes;
    (bytes.append(reinterpret_cast<const char*>(&values), sizeof values), ...);
    return bytes;
}

// Three float vertices and one face of uchar count and int indices; the body starts at its size.
const std::string kBinaryTriangleHeader =
    "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
    "element face 1\nproperty list uchar int vertex_indices\nend_header\n";

// (0, 0, 0) (1, 0, 0) (0, 1, 0): 36 bytes.
const std::string kTriangleFloats = little_endian(0.0f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f, 0.0f, 1.0f, 0.0f);

std::string at_byte(size_t offset) { return "byte offset " + std::to_string(offset); }

std::vector<Rejection> rejections() {
    const std::string xyz = "property float x\nproperty float y\nproperty float z\n";
    const std::string ascii_header = "ply\nformat ascii 1.0\n";
    const std::string truncated = kBinaryTriangleHeader + kTriangleFloats + little_endian(uint8_t{3}, 0, 1);
    const std::string huge_vertex_header = "ply\nformat binary_little_endian 1.0\nelement vertex 10000000\n" + xyz +
                                           "element face 0\nproperty list uchar int vertex_indices\nend_header\n";
    const std::string char_count_header = "ply\nformat binary_little_endian 1.0\nelement vertex 3\n" + xyz +
                                          "element face 1\nproperty list char int vertex_indices\nend_header\n";
    const float nan = std::numeric_limits<float>::quiet_NaN();
    std::string many_corners = "1025";
    for (int i = 0; i < 1025; ++i) many_corners += " 0";
    return {
        // The magic line.
        {"empty", "", 1, {"magic"}},
        {"magicMisspelt", "plx\nformat ascii 1.0\n", 1, {"magic"}},
        {"magicInCapitals", "PLY\n", 1, {"magic"}},
        {"magicAfterABlankLine", "\nply\n", 1, {"magic"}},
        {"noMagicLine", "format ascii 1.0\nend_header\n", 1, {"magic"}},
        // The format line.
        {"unknownFormat", "ply\nformat utf8 1.0\nelement vertex 0\nend_header\n", 2, {"unknown PLY format 'utf8'"}},
        {"unknownVersion", "ply\nformat ascii 2.0\nend_header\n", 2, {"version"}},
        {"noFormatLine", "ply\nelement vertex 0\nproperty float x\nend_header\n", 4, {"format"}},
        {"bigEndian", "ply\nformat binary_big_endian 1.0\nelement vertex 0\nproperty float x\nend_header\n", 2,
         {"unsupported", "binary_big_endian"}},
        // Property types.
        {"unknownScalarType", ascii_header + "element vertex 1\nproperty float x\nproperty real y\nend_header\n", 5,
         {"unknown property type 'real'"}},
        {"unknownListType", ascii_header + "element face 1\nproperty list uchar int64 vertex_indices\nend_header\n", 4,
         {"unknown property type 'int64'"}},
        {"floatListCount", ascii_header + "element face 1\nproperty list float int vertex_indices\nend_header\n", 4,
         {"count type"}},
        // Header lines.
        {"unknownKeyword", ascii_header + "elemnt vertex 1\nend_header\n", 3, {"unknown header keyword 'elemnt'"}},
        {"propertyBeforeAnyElement", ascii_header + "property float x\nend_header\n", 3, {"before any 'element'"}},
        {"noEndHeader", ascii_header + "element vertex 1\nproperty float x\n", 4, {"end_header"}},
        {"vertexWithoutYAndZ", ascii_header + "element vertex 1\nproperty float x\nend_header\n0\n", 3,
         {"x, y and z"}},
        {"partialColour",
         ascii_header + "element vertex 1\n" + xyz +
             "property uchar red\nproperty uchar green\nend_header\n0 0 0 1 1\n",
         3, {"red, green, blue"}},
        {"intColour",
         ascii_header + "element vertex 1\n" + xyz +
             "property int red\nproperty int green\nproperty int blue\nend_header\n0 0 0 1 1 1\n",
         7, {"unsupported colour type int"}},
        // Counts in the header.
        {"negativeElementCount", ascii_header + "element vertex -3\nproperty float x\nend_header\n", 3,
         {"negative count"}},
        {"vertexCountOverTheLimit",  // must fail on the header line, without allocating or reading a body
         "ply\nformat binary_little_endian 1.0\nelement vertex 4000000000\n" + xyz + "end_header\n", 3,
         {"too many vertices: 4000000000"}},
        {"faceCountOverTheLimit", ascii_triangle(kTriangleVertices, "3 0 1 2\n", 3, (1 << 24) + 1), 7,
         {"too many faces"}},
        {"countPastUint64", ascii_header + "element vertex 99999999999999999999999\nend_header\n", 3, {"too large"}},
        // Ascii bodies.
        {"asciiBodyCutShort", ascii_triangle("0 0 0\n1 0 0\n", ""), 12, {"truncated"}},
        {"asciiLineCutShort", ascii_triangle("0 0 0\n1 0\n0 1 0\n"), 11, {"line ends early"}},
        {"asciiCountTheBodyCannotHold", ascii_triangle(kTriangleVertices, "3 0 1 2\n", 3, 16000000), 14,
         {"truncated body", "face 1 (0-based) of 16000000"}},
        {"wordForACoordinate", ascii_triangle("0 0 0\n1 zero 0\n0 1 0\n"), 11, {"test.ply:11:3:", "'zero'"}},
        {"fractionForAnIndex", ascii_triangle(kTriangleVertices, "3 0 1.5 2\n"), 13, {"'1.5'"}},
        {"countPastItsType", ascii_triangle(kTriangleVertices, "256 0 1 2\n"), 13, {"out of range for type uchar"}},
        {"extraTokenOnAVertexLine", ascii_triangle("0 0 0\n1 0 0 7\n0 1 0\n"), 11, {"extra tokens"}},
        {"extraTokenOnAFaceLine", ascii_triangle(kTriangleVertices, "3 0 1 2 0\n"), 13, {"extra tokens"}},
        {"asciiDataAfterTheLastElement", ascii_triangle(kTriangleVertices, "3 0 1 2\n\n3 0 1 2\n"), 15,
         {"after the last element"}},
        {"asciiIndexPastTheVertices", ascii_triangle(kTriangleVertices, "3 0 1 2\n3 2 3 1\n", 3, 2), 14,
         {"face 1", "vertex index 3 out of range"}},
        {"asciiNegativeIndex", ascii_triangle(kTriangleVertices, "3 0 -1 2\n"), 13,
         {"face 0", "vertex index -1 out of range"}},
        {"asciiNegativeListCount",
         ascii_header + "element vertex 1\n" + xyz + "property list int float extra\nend_header\n0 0 0 -2\n", 9,
         {"negative list count -2"}},
        {"faceOverThePolygonLimit",
         ascii_header + "element vertex 1\n" + xyz +
             "element face 1\nproperty list ushort int vertex_indices\nend_header\n0 0 0\n" + many_corners + "\n",
         11, {"1025 vertices (limit 1024)"}},
        {"faceOfTwoCorners", ascii_triangle(kTriangleVertices, "2 0 1\n"), 13, {"face 0 (0-based) has 2 vertices"}},
        {"asciiNan", ascii_triangle("0 0 0\n1 nan 0\n0 1 0\n"), 11, {"y coordinate"}},
        {"asciiInfinity", ascii_triangle("0 0 0\n1 inf 0\n0 1 0\n"), 11, {"y coordinate"}},
        {"asciiMinusInfinity", ascii_triangle("0 0 0\n1 -inf 0\n0 1 0\n"), 11, {"y coordinate"}},
        {"asciiPastTheFloatRange", ascii_triangle("0 0 0\n1 1e39 0\n0 1 0\n"), 11, {"y coordinate"}},
        {"asciiPastTheDoubleRange", ascii_triangle("0 0 0\n1 0 1e999\n0 1 0\n"), 11, {"out of range"}},
        // Binary bodies.
        {"binaryBodyCutShort", truncated, 0, {"truncated", at_byte(truncated.size())}},  // the last index missing
        {"binaryCountTheBodyCannotHold", huge_vertex_header + little_endian(0.0f, 0.0f, 0.0f), 0,
         {"truncated body", "vertex 1 (0-based) of 10000000", at_byte(huge_vertex_header.size() + 12)}},
        {"binaryListTheBodyCannotHold",  // a list of 4 billion doubles in a 4-byte body
         "ply\nformat binary_little_endian 1.0\nelement vertex 0\n" + xyz +
             "element edge 18446744073709551615\nproperty list uint double a\nend_header\n" +
             little_endian(uint32_t{0xffffffff}),
         0, {"truncated body", "edge 0 (0-based)"}},
        {"binaryDataAfterTheLastElement",
         kBinaryTriangleHeader + kTriangleFloats + little_endian(uint8_t{3}, 0, 1, 2, uint8_t{9}), 0,
         {"1 unexpected bytes after the last element"}},
        {"binaryIndexPastTheVertices", kBinaryTriangleHeader + kTriangleFloats + little_endian(uint8_t{3}, 0, 7, 2), 0,
         {"face 0", "vertex index 7 out of range", at_byte(kBinaryTriangleHeader.size() + 36 + 1 + 4)}},
        {"binaryNegativeListCount", char_count_header + kTriangleFloats + little_endian(int8_t{-1}, 0, 1, 2), 0,
         {"negative list count -1", at_byte(char_count_header.size() + 36)}},
        {"binaryNan",
         kBinaryTriangleHeader + little_endian(0.0f, 0.0f, 0.0f, 1.0f, nan, 0.0f, 0.0f, 1.0f, 0.0f) +
             little_endian(uint8_t{3}, 0, 1, 2),
         0, {"non-finite y coordinate", at_byte(kBinaryTriangleHeader.size() + 16)}},
    };
}

class PlyRejection : public testing::TestWithParam<Rejection> {};

TEST_P(PlyRejection, isAnInputErrorAtItsLineNamingTheProblem) {
    const Rejection& r = GetParam();
    try {
        parse_ply(r.bytes, "test.ply");
        ADD_FAILURE() << "accepted";
    } catch (const InputError& e) {
        const std::string what = e.what();
        EXPECT_EQ(e.line(), r.line) << what;
        for (const std::string& part : r.parts)
            EXPECT_NE(what.find(part), std::string::npos) << what << " lacks " << part;
    }
}

INSTANTIATE_TEST_SUITE_P(PlyLoader, PlyRejection, testing::ValuesIn(rejections()),
                         [](const testing::TestParamInfo<Rejection>& info) { return std::string(info.param.name); });

}  // namespace
