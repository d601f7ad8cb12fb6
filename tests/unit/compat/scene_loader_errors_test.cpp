// Scene loader tests, bad input: one table of rejected scenes, each an InputError naming the file, the line and
// column of the problem and the problem itself; and the values just inside each limit, which are read.
#include <ostream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/support/temp_dir.h"

#include "raster/core/errors.h"
#include "raster/compat/scene_loader.h"

namespace raster::scene_loader_tests {

// The seed 003 scene of scene_loader_seed003_test.cpp, where it is defined and described.
std::string seed003_scene(const std::string& obj, const std::string& near, const std::string& far);

}  // namespace raster::scene_loader_tests

namespace {

using raster::InputError;
using raster::parse_scene;
using raster::scene_loader_tests::seed003_scene;
using raster::test_support::TempDir;

testing::AssertionResult contains(const std::string& text, const std::string& part) {
    if (text.find(part) != std::string::npos) return testing::AssertionSuccess();
    return testing::AssertionFailure() << "'" << text << "' does not contain '" << part << "'";
}

const std::string kTriangle = "  - vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0]]\n    faces: [[0, 1, 2]]\n";
// A raster scene: `sections` (whole top-level keys, each line ending in '\n') and then the triangle mesh.
std::string with_triangle(const std::string& sections) { return sections + "meshes:\n" + kTriangle; }
// The triangle mesh with more of its keys (lines indented 4 spaces) after `faces`.
std::string triangle_with(const std::string& keys) { return "meshes:\n" + kTriangle + keys; }
std::string block_nesting(int levels) {
    std::string text;
    for (int i = 0; i < levels; ++i) text += "- ";
    return text + "x\n";
}

// One scene that must be rejected, and what the rejection must say.
struct Rejection {
    const char* name;  // the test's name
    std::string text;
    int line;
    int column;  // 0: not checked
    std::string problem;
    std::vector<std::string> also = {};   // more the message must hold; "{folder}" stands for the test's folder
    std::vector<std::string> never = {};  // what it must not hold
    std::string file = "scene.yaml";      // the name parse_scene is given, which the error must repeat
    bool in_folder = false;  // read as `file` in a folder of mesh files: tri.obj, and cut.obj and cut2.obj cut short
};

void PrintTo(const Rejection& rejection, std::ostream* out) { *out << rejection.name; }

const std::vector<Rejection> kRejections = {
    {"meshesAreRequired", "image: {width: 10, height: 10}\n", 1, 0, "meshes"},
    // Transform chains: the error points at the step.
    {"transformWithZeroRotateAxis", triangle_with("    transform:\n      - rotate: [90, 0, 0, 0]\n"), 5, 17, "axis"},
    {"transformWithUnknownStep", triangle_with("    transform:\n      - shear: 2\n"), 5, 9, "unknown key 'shear'"},
    // Inline meshes: per-vertex and per-face lists of the wrong length, and a face of 2 corners.
    {"inlineVertexColorsCountMismatch", triangle_with("    vertex_colors: [[1, 0, 0], [0, 1, 0]]\n"), 4, 20,
     "one entry per vertex"},
    {"inlineFaceColorsCountMismatch", triangle_with("    face_colors: [[1, 0, 0], [0, 1, 0]]\n"), 4, 18,
     "one entry per face"},
    {"inlineNormalsCountMismatch", triangle_with("    normals: [[0, 0, 1]]\n"), 4, 14, "one entry per vertex"},
    {"inlineFaceOfTwoCorners", "meshes:\n  - vertices: [[0, 0, 0], [1, 0, 0]]\n    faces: [[0, 1]]\n", 3, 13,
     "3 or more"},
    // Syntax. Line 3 is indented one space: neither inside `image` nor at the top level.
    {"yamlSyntaxError", "image:\n  width: 10\n height: 5\nmeshes: []\n", 3, 2, "YAML syntax error"},
    // The second comma of line 3 ("    1,,") is column 7.
    {"jsonSyntaxError", "{\n  \"meshes\": [\n    1,,\n  ]\n}\n", 3, 7, "JSON syntax error", {"','"},
     {"json.exception"}, "scene.json"},
    // A trailing comma (valid YAML flow, invalid JSON) is a JSON error: line 2, column 14 is '}'.
    {"jsonTrailingComma", "{\"meshes\": [],\n \"image\": {},}\n", 2, 14, "JSON syntax error", {}, {}, "scene.json"},
    // Unknown keys: a near miss names the key meant, anything else lists the choices.
    {"unknownKeyNearAKnownOne", with_triangle("camera:\n  fow: 30\n"), 2, 3, "unknown key 'fow'",
     {"did you mean 'fov'"}},
    {"unknownKeyFarFromEveryKnownOne", with_triangle("render:\n  quality: high\n"), 2, 3, "unknown key 'quality'",
     {"samples"}},
    // A string, a list, and a string in a vector where numbers are expected.
    {"stringForANumber", with_triangle("image:\n  width: wide\n"), 2, 10, "number", {"width", "wide"}},
    {"listForANumber", with_triangle("camera:\n  fov: [45]\n"), 2, 8, "number"},
    {"stringInAVector", with_triangle("camera:\n  eye: [0, one, 5]\n"), 2, 12, "number"},
    // The camera. "  near: " is 8 characters: the value is at column 9 of line 3.
    {"nearNegative", with_triangle("camera:\n  eye: [0, 0, 5]\n  near: -1\n"), 3, 9, "near must be > 0"},
    {"nearZero", with_triangle("camera:\n  fov: 45\n  near: 0\n"), 3, 9, "near must be > 0"},
    {"farBeforeNear", with_triangle("camera:\n  near: 10\n  far: 5\n"), 3, 8, "far", {"near"}},
    {"farAtNear", with_triangle("camera:\n  near: 10\n  far: 10\n"), 3, 8, "far"},
    // Past 2^126 (8.5e37) 1 / far is a subnormal float.
    {"farPastANormalInverse", with_triangle("camera:\n  far: 1e38\n"), 2, 8, "far must be at most 8.50706e+37"},
    // far left at its default 100: the near value is the one to blame.
    {"nearBeyondTheDefaultFar", with_triangle("camera:\n  fov: 30\n  near: 200\n"), 3, 9, "far"},
    {"fieldOfViewZero", with_triangle("camera:\n  fov: 0\n"), 2, 8, "(0, 180)"},
    {"fieldOfView180", with_triangle("camera:\n  near: 1\n  fov: 180\n"), 3, 8, "(0, 180)"},
    {"eyeAtTheTarget", with_triangle("camera:\n  eye: [1, 2, 3]\n  target: [1, 2, 3]\n"), 3, 11, "same point"},
    // Eye above the default target: the view direction is -y, parallel to up.
    {"upAlongTheViewDirection", with_triangle("camera:\n  eye: [0, 5, 0]\n  up: [0, 1, 0]\n"), 3, 7, "parallel"},
    {"upAgainstTheViewDirection", with_triangle("camera:\n  eye: [0, 5, 0]\n  up: [0, -2, 0]\n"), 3, 7, "parallel"},
    {"upZero", with_triangle("camera:\n  eye: [0, 0, 5]\n  up: [0, 0, 0]\n"), 3, 7, "up"},
    // Lights: a type, what places it (a directional light no position, a point light no direction), and the light
    // check (a directional light casts no shadows; a spot light's inner cone is inside its outer one).
    {"lightTypeUnknown", with_triangle("lights:\n  - {type: sun, direction: [0, -1, 0]}\n"), 2, 12,
     "light type must be point, directional or spot"},
    {"directionalWithAPosition", with_triangle("lights:\n  - {type: directional, position: [0, 1, 0]}\n"), 2, 35,
     "a directional light has a direction, not a position"},
    {"directionalCastingShadows",
     with_triangle("lights:\n  - {type: directional, direction: [0, -1, 0], shadows: true}\n"), 2, 5,
     "casts no shadows"},
    {"spotConesCrossed",
     with_triangle("lights:\n  - {type: spot, position: [0, 2, 0], direction: [0, -1, 0], inner_cone: 40, "
                   "outer_cone: 30}\n"),
     2, 5, "cone angles must be 0 <= inner_cone < outer_cone <= 90 degrees"},
    // Orthographic cameras: a height, not a field of view; near may be 0 but not less.
    {"projectionUnknown", with_triangle("camera:\n  projection: isometric\n"), 2, 15, "perspective or orthographic"},
    {"fieldOfViewOnAnOrthographicCamera", with_triangle("camera:\n  projection: orthographic\n  fov: 30\n"), 3, 8,
     "takes height"},
    {"heightOnAPerspectiveCamera", with_triangle("camera:\n  height: 4\n"), 2, 11, "orthographic"},
    {"orthographicHeightZero", with_triangle("camera:\n  projection: orthographic\n  height: 0\n"), 3, 11,
     "height must be finite and > 0"},
    {"orthographicNearNegative", with_triangle("camera:\n  projection: orthographic\n  near: -1\n"), 3, 9,
     "near must be >= 0"},
    // Column 20 of "    faces: [[0, 1, 3]]" is the 3.
    {"faceIndexPastTheLastVertex",
     "meshes:\n  - vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0]]\n    faces: [[0, 1, 3]]\n", 3, 20, "0..2", {"3"}},
    {"faceIndexNegative", "meshes:\n  - vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0]]\n    faces: [[0, -1, 2]]\n", 3,
     17, "0..2"},
    // Numbers that are not finite. "  background: [" is 15 characters: the first component is at column 16.
    {"notANumber", with_triangle("image:\n  background: [.nan, 0, 0]\n"), 2, 16, ".nan"},
    {"infinity", with_triangle("image:\n  background: [.inf, 0, 0]\n"), 2, 16, ".inf"},
    {"minusInfinity", with_triangle("image:\n  background: [-.inf, 0, 0]\n"), 2, 16, "-.inf"},
    {"notANumberCapitalised", with_triangle("image:\n  background: [.NaN, 0, 0]\n"), 2, 16, ".NaN"},
    {"overflow", with_triangle("image:\n  background: [1e999, 0, 0]\n"), 2, 16, "1e999"},
    {"negativeOverflow", with_triangle("image:\n  background: [-1e999, 0, 0]\n"), 2, 16, "-1e999"},
    {"floatOverflowInAVertex", "meshes:\n  - vertices: [[0, 0, 0], [1, 0, 0], [0, 1e39, 0]]\n    faces: [[0, 1, 2]]\n",
     2, 42, "1e39"},
    {"notANumberInATransform", triangle_with("    transform:\n      - translate: [0, .nan, 0]\n"), 5, 24, ".nan"},
    // Image size and frame memory.
    {"widthOver16384", with_triangle("image:\n  width: 16385\n"), 2, 10, "16384"},
    {"heightOver16384", with_triangle("image:\n  width: 10\n  height: 100000\n"), 3, 11, "16384"},
    {"widthZero", with_triangle("image:\n  width: 0\n"), 2, 10, "1.."},
    // 16384 x 16384 x 16 samples x 28 bytes is far over 4 GiB; the sample count is the value to change.
    {"framesOverTheMemoryCapBySamples", with_triangle("image: {width: 16384, height: 16384}\nrender:\n  samples: 16\n"),
     3, 12, "MiB"},
    // Even one sample is 16384^2 x 32 bytes = 8 GiB: the image size is to blame.
    {"framesOverTheMemoryCapBySize", with_triangle("image: {width: 16384, height: 16384}\n"), 1, 8, "MiB"},
    // Sample counts: grids need a square count; the standard pattern has no 3 and no 9.
    {"sampleCountNotInTheStandardPattern", with_triangle("render:\n  pattern: standard\n  samples: 3\n"), 3, 12, "3",
     {"standard"}},
    {"sampleCountNotASquareForAGrid", with_triangle("render:\n  samples: 8\n  pattern: grid\n"), 2, 12, "8"},
    {"sampleCount9WithTheDefaultPattern", with_triangle("render:\n  samples: 9\n"), 2, 12, "9"},
    // Mesh files: the scene's line, and the mesh's path or own line. "  - file: " is 10 characters.
    {"missingMeshFile", triangle_with("  - file: models/nothere.obj\n"), 4, 11, "models/nothere.obj",
     {"{folder}/models/nothere.obj"}, {}, "scene.yaml", true},
    // cut.obj ends in the middle of its third vertex, cut2.obj inside its second face line.
    {"objCutShortInAVertex", "meshes:\n  - file: cut.obj\n", 2, 11, "cut.obj", {"cut.obj:3:"}, {}, "scene.yaml", true},
    {"objCutShortInAFace", "meshes:\n  - file: cut2.obj\n", 2, 11, "cut2.obj", {"cut2.obj:6:"}, {}, "scene.yaml",
     true},
    // Nesting: the 65th '[' is column 73 of line 2; the 65th "- " starts at column 129.
    {"flowNestingOf65Levels", "image: {width: 10}\nmeshes: " + std::string(65, '[') + std::string(65, ']') + "\n", 2,
     73, "nesting", {"64"}},
    {"blockNestingOf10000Levels", block_nesting(10000), 1, 129, "nesting"},
    // Documents that are no scene.
    {"emptyFile", "", 1, 1, "empty"},
    {"onlyBlankLines", "\n\n   \n", 1, 1, "empty"},
    {"onlyAComment", "# just a comment\n", 1, 1, "empty"},
    {"aListAtTheTop", "- 1\n- 2\n", 1, 1, "map"},
    // Seed 003: the obj path is relative to the scene file, which here has no models/ beside it.
    {"seed003ObjNotBesideTheScene", seed003_scene("models/tri.obj", "-0.1", "-100"), 11, 22, "models/tri.obj", {}, {},
     "x.json", true},
    // "  \"near\": " is 10 characters: the value starts in column 11 of line 8.
    {"seed003NearNegativeFarPositive", seed003_scene("tri.obj", "-0.1", "100"), 8, 11, "near", {}, {}, "s.json", true},
    {"seed003NearPositiveFarNegative", seed003_scene("tri.obj", "0.1", "-100"), 8, 11, "near", {}, {}, "s.json", true},
    // Book order reversed (near -100 is farther than far -0.1): far is not beyond near.
    {"seed003FarBeforeNear", seed003_scene("tri.obj", "-100", "-0.1"), 9, 10, "far", {}, {}, "s.json", true},
    // Seed 001: a transform step is a map with one key; column 27 is the step's '{'.
    {"seed001TransformStepOfTwoKeys",
     "{\"camera\": {\"transform\": [{\"scale\": 2, \"translate\": [1, 2, 3]}]}, \"objects\": []}\n", 1, 27,
     "each transform step is a map with one key", {}, {}, "balboa.json"},
};

class SceneRejection : public testing::TestWithParam<Rejection> {};

TEST_P(SceneRejection, namesTheFileLineColumnAndProblem) {
    const Rejection& rejection = GetParam();
    TempDir folder;
    folder.write("tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    folder.write("cut.obj", "v 0 0 0\nv 1 0 0\nv 0 1");
    folder.write("cut2.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\nf 2 4");
    const std::string file = rejection.in_folder ? (folder.path() / rejection.file).string() : rejection.file;
    try {
        parse_scene(rejection.text, file);
        ADD_FAILURE() << "no InputError for input that must be rejected (" << rejection.problem << ")";
    } catch (const InputError& error) {
        EXPECT_EQ(error.file(), file) << error.what();
        EXPECT_EQ(error.line(), rejection.line) << error.what();
        if (rejection.column > 0) {
            EXPECT_EQ(error.column(), rejection.column) << error.what();
        }
        // The full message starts with "file:line:", as docs/cli.md's example shows.
        EXPECT_TRUE(contains(error.what(), file + ":" + std::to_string(rejection.line) + ":"));
        EXPECT_TRUE(contains(error.message(), rejection.problem));
        for (std::string part : rejection.also) {
            if (const size_t at = part.find("{folder}"); at != std::string::npos)
                part.replace(at, 8, folder.path().string());
            EXPECT_TRUE(contains(error.message(), part));
        }
        for (const std::string& part : rejection.never) EXPECT_FALSE(contains(error.message(), part)) << part;
    }
}

INSTANTIATE_TEST_SUITE_P(SceneLoader, SceneRejection, testing::ValuesIn(kRejections),
                         [](const testing::TestParamInfo<Rejection>& info) { return std::string(info.param.name); });

// ---------------------------------------------------------------------------------------------------------------
// Just inside each limit: read, not refused

TEST(SceneLoader, rejectsAMeshWithNeitherFileNorVertices) {
    EXPECT_THROW(parse_scene("meshes:\n  - faces: [[0, 1, 2]]\n", "scene.yaml"), InputError);
}

TEST(SceneLoader, readsFieldsOfViewJustInsideTheOpenInterval) {
    EXPECT_NO_THROW(parse_scene(with_triangle("camera:\n  fov: 179\n"), "scene.yaml"));
    EXPECT_NO_THROW(parse_scene(with_triangle("camera:\n  fov: 0.5\n"), "scene.yaml"));
}

// The projection's terms must fit a float: its scale terms grow as 1 / tan(fov / 2), its depth terms as
// n f / (f - n). Each refusal names the camera value to change.
TEST(SceneLoader, refusesAProjectionWhoseTermsOverflowFloat) {
    const std::pair<std::string, std::string> cases[] = {
        // 1 / tan(1e-37 degrees / 2) is about 1.1e39, past the largest float (3.4e38).
        {"camera:\n  fov: 1e-37\n", "camera field of view 1e-37 degrees is too narrow"},
        // near and far a float apart (about 1e28) at 1e35: n f / (f - n) is about 1e42.
        {"camera:\n  near: 1e35\n  far: 1.0000001e35\n", "are too close for their size"},
    };
    for (const auto& [camera, problem] : cases) {
        try {
            parse_scene(with_triangle(camera), "scene.yaml");
            ADD_FAILURE() << "no InputError for " << camera;
        } catch (const InputError& error) {
            EXPECT_EQ(error.file(), "scene.yaml");
            EXPECT_TRUE(contains(error.message(), problem)) << error.message();
        }
    }
}

TEST(SceneLoader, reads16384By1Pixels) {
    // 16384 x 1 is within every limit.
    EXPECT_NO_THROW(parse_scene(with_triangle("image: {width: 16384, height: 1}\n"), "scene.yaml"));
}

TEST(SceneLoader, readsFrameBuffersUpToTheMemoryCap) {
    // docs: 28 bytes per sample plus 4 per pixel, at most 4 GiB. At 16 samples that is 452 bytes a pixel:
    // 3082 x 3083 pixels need 4,294,816,312 bytes (fits), 3083 x 3083 need 4,296,209,828 (does not).
    EXPECT_NO_THROW(parse_scene(with_triangle("image: {width: 3082, height: 3083}\nrender: {samples: 16}\n"),
                                "scene.yaml"));
    EXPECT_THROW(
        parse_scene(with_triangle("image: {width: 3083, height: 3083}\nrender: {samples: 16}\n"), "scene.yaml"),
        InputError);
    // docs' example: 800 x 800 at 16 samples is fine.
    EXPECT_NO_THROW(
        parse_scene(with_triangle("image: {width: 800, height: 800}\nrender: {samples: 16}\n"), "scene.yaml"));
}

TEST(SceneLoader, readsEverySampleCountItsPatternHas) {
    for (const char* ok : {"{samples: 1}", "{samples: 2}", "{samples: 4}", "{samples: 8}", "{samples: 16}",
                           "{samples: 9, pattern: grid}", "{samples: 16, pattern: grid}"})
        EXPECT_NO_THROW(parse_scene(with_triangle(std::string("render: ") + ok + "\n"), "scene.yaml")) << ok;
}

TEST(SceneLoader, readsNestingOf64LevelsAndBracketsInComments) {
    // 64 levels are parsed (and then refused for what they contain, not for their depth).
    try {
        parse_scene("image: {width: 10}\nmeshes: " + std::string(64, '[') + std::string(64, ']') + "\n", "scene.yaml");
        ADD_FAILURE() << "64 nested empty lists are no meshes";
    } catch (const InputError& error) {
        EXPECT_FALSE(contains(error.message(), "nesting"));
    }
    // Brackets inside comments do not count.
    EXPECT_NO_THROW(parse_scene("# " + std::string(65, '[') + std::string(65, ']') + "\nimage: {background: 0}\n" +
                                    "meshes:\n" + kTriangle,
                                "scene.yaml"));
}

}  // namespace
