// Seed 000 (YAML tasks): the document's examples run unchanged, and each task does what the document defines:
// eq. (1) with a lower-left origin, per-object transforms, the transform-test's depth convention, the depth image
// and Blinn-Phong with 1/r^2 attenuation. Expectations are computed here from the document's formulas.
#include "raster/compat/scene_format_seed000.h"

#include <cmath>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "raster/compat/scene_loader.h"
#include "tests/support/seed_test_support.h"

namespace raster {
namespace {

using namespace seed_test;

std::string replaced(std::string text, const std::string& from, const std::string& to) {
    const size_t at = text.find(from);
    if (at == std::string::npos) throw std::runtime_error("'" + from + "' not in the text");
    return text.replace(at, from.size(), to);
}

// ---- transform-test ----

TEST(Seed000, documentsTransformTestMatchesItsExpectedValue) {
    TempDir dir;
    dir.copy_corpus("seeds/000");
    const CliResult result = run_raster({"render", (dir / "test-transform-test.yaml").string()});
    EXPECT_EQ(result.status, 0) << result.out << result.err;
    EXPECT_TRUE(contains(result.out, "match"));
    EXPECT_FALSE(fs::exists(dir / "output.png"));  // a transform-test prints; it draws nothing

    // The document's numbers: the origin seen from (0, 0, 5) is at depth d = 5, on the axis (pixel 400, 400).
    // Its depth row, solved from a3 + a4/n = n and a3 + a4/f = f with n = -0.1 and f = -100, is OpenGL's NDC z
    // negated: -((f + n) / (f - n) - 2 f n / ((f - n) d)) in distances, which is -0.961962 (printed as -0.962).
    const double n = 0.1, f = 100.0, d = 5.0;
    const double depth = -((f + n) / (f - n) - 2.0 * f * n / ((f - n) * d));
    const Seed000TestResult test = run_seed000_transform_test(load_seed000_config(dir / "test-transform-test.yaml"));
    EXPECT_NEAR(test.transformed.x, 400.0, 1e-9);
    EXPECT_NEAR(test.transformed.y, 400.0, 1e-9);
    EXPECT_NEAR(test.transformed.z, depth, 1e-9);
    EXPECT_NEAR(test.transformed.w, 1.0, 1e-12);
    EXPECT_TRUE(test.match);
}

TEST(Seed000, transformTestOutsideTheDocumentedToleranceExitsOne) {
    TempDir dir;
    dir.copy_corpus("seeds/000");
    const std::string text = read_text(dir / "test-transform-test.yaml");
    auto run_with = [&](const std::string& expected) {
        const fs::path config = dir.write("t.yaml", replaced(text, "[400.0, 400.0, -0.962, 1.0]", expected));
        return run_raster({"render", config.string()});
    };
    // Tolerance 1e-3 + 1e-5 |expected| per component; z is -0.961962.
    EXPECT_EQ(run_with("[400.0, 400.0, -0.9629, 1.0]").status, 0);  // off by 0.00094
    const CliResult z_off = run_with("[400.0, 400.0, -0.9631, 1.0]");  // off by 0.00114
    EXPECT_EQ(z_off.status, 1);
    EXPECT_TRUE(contains(z_off.out, "MISMATCH"));
    EXPECT_EQ(run_with("[401.0, 400.0, -0.962, 1.0]").status, 1);
    EXPECT_EQ(run_with("[400.0, 400.0, -0.962, 5.0]").status, 1);  // w after the divide is 1
}

// The document's projection conditions: near-plane points stay put (z = +1 after the divide here, near is
// nearest), the far plane's axis point goes to z = -1, and the near-plane rectangle fills the canvas with the
// origin at the lower left.
TEST(Seed000, transformTestFollowsTheDocumentsProjectionConditions) {
    Seed000Config config;
    config.task = Seed000Task::transform_test;
    config.width = 200;
    config.height = 100;
    Seed000Camera camera;
    camera.pos = glm::vec3(0.0f);
    camera.look_at = glm::vec3(0.0f, 0.0f, -1.0f);
    camera.width = 4.0f;
    camera.height = 2.0f;
    camera.near_clip = 2.0f;
    camera.far_clip = 50.0f;
    config.camera = camera;
    auto through = [&](glm::dvec3 input) {
        config.input = input;
        return run_seed000_transform_test(config).transformed;
    };
    EXPECT_NEAR(through({0, 0, -2}).z, 1.0, 1e-12);
    EXPECT_NEAR(through({0, 0, -50}).z, -1.0, 1e-12);
    const glm::dvec4 top_right = through({2, 1, -2}), bottom_left = through({-2, -1, -2});
    EXPECT_NEAR(top_right.x, 200.0, 1e-9);
    EXPECT_NEAR(top_right.y, 100.0, 1e-9);
    EXPECT_NEAR(bottom_left.x, 0.0, 1e-9);
    EXPECT_NEAR(bottom_left.y, 0.0, 1e-9);
    const glm::dvec4 twice_as_far = through({4, 2, -4});  // perspective: the same pixel
    EXPECT_NEAR(twice_as_far.x, 200.0, 1e-9);
    EXPECT_NEAR(twice_as_far.y, 100.0, 1e-9);
    EXPECT_LT(twice_as_far.z, 1.0);
}

// ---- triangle ----

const char* kTriangleConfig =
    "task: triangle\n"
    "antialias: SSAA\n"
    "samples: 16\n"
    "resolution:\n"
    "    width: 64\n"
    "    height: 48\n"
    "obj: tri\n"
    "output: out\n";

std::string one_triangle_obj(double x0, double y0, double x1, double y1, double x2, double y2) {
    std::ostringstream text;
    text << "v " << x0 << ' ' << y0 << " 0.3\nv " << x1 << ' ' << y1 << " -0.7\nv " << x2 << ' ' << y2 << " 0\nf 1 2 3\n";
    return text.str();
}

TEST(Seed000, triangleTaskCoversTheCanvasAreaOfEquationOne) {
    TempDir dir;
    const double x[3] = {-0.8, 0.7, -0.1}, y[3] = {-0.6, -0.2, 0.9};
    dir.write("tri.obj", one_triangle_obj(x[0], y[0], x[1], y[1], x[2], y[2]));
    const fs::path config = dir.write("cfg.yaml", kTriangleConfig);
    const CliResult result = run_raster({"render", config.string(), "-o", (dir / "out.ppm").string()});
    ASSERT_EQ(result.status, 0) << result.err;
    const Pixels image = read_pnm(dir / "out.ppm");
    ASSERT_EQ(image.width, 64);
    ASSERT_EQ(image.height, 48);

    // Eq. (1): x' = w/2 (1 + x), y' = h/2 (1 + y); the area is independent of the row order.
    double cx[3], cy[3];
    for (int i = 0; i < 3; ++i) cx[i] = 32.0 * (1 + x[i]), cy[i] = 24.0 * (1 + y[i]);
    const double area = 0.5 * std::fabs((cx[1] - cx[0]) * (cy[2] - cy[0]) - (cx[2] - cx[0]) * (cy[1] - cy[0]));
    // A 4x4 grid misestimates a pixel that one edge crosses by less than 1/4 of it; an edge crosses at most
    // |dx| + |dy| + 2 pixels; the three corner pixels may be wrong entirely; bytes round by 0.5/255.
    double crossed = 0.0;
    for (int i = 0; i < 3; ++i) {
        const int j = (i + 1) % 3;
        crossed += std::fabs(cx[j] - cx[i]) + std::fabs(cy[j] - cy[i]) + 2.0;
    }
    const double bound = crossed / 4.0 + 3.0 + crossed * 0.5 / 255.0;
    double coverage = 0.0;
    for (int py = 0; py < image.height; ++py)
        for (int px = 0; px < image.width; ++px) {
            const uint8_t* p = image.at(px, py);
            EXPECT_TRUE(p[0] == p[1] && p[1] == p[2]) << "white on black only";
            coverage += p[0] / 255.0;
        }
    EXPECT_NEAR(coverage, area, bound);
    EXPECT_GT(area, 10.0 * bound);  // the check is not vacuous
}

TEST(Seed000, triangleTaskOriginIsTheLowerLeftCorner) {
    TempDir dir;
    // Canvas y' in [0.9 h, h]: the top tenth of the picture.
    dir.write("tri.obj", one_triangle_obj(-0.5, 0.8, 0.5, 0.8, 0.0, 1.0));
    const fs::path config = dir.write("cfg.yaml", kTriangleConfig);
    ASSERT_EQ(run_raster({"render", config.string(), "-o", (dir / "out.ppm").string()}).status, 0);
    const Pixels image = read_pnm(dir / "out.ppm");
    int lit = 0;
    for (int py = 0; py < image.height; ++py)
        for (int px = 0; px < image.width; ++px)
            if (image.at(px, py)[0] > 0) {
                ++lit;
                EXPECT_LT(py, 6) << "lit pixel at row " << py << " (rows are written top first)";
            }
    EXPECT_GT(lit, 50);
}

// ---- transform ----

const char* kTwoObjectsObj =
    "o first\nv -0.5 -0.5 0\nv 0.5 -0.5 0\nv 0 0.5 0\nf 1 2 3\n"
    "o second\nv -0.5 -0.5 0\nv 0.5 -0.5 0\nv 0 0.5 0\nf 4 5 6\n";

// A camera at (0, 0, 5) looking at the origin with a 90 degree view (0.2 wide at near 0.1), 100 x 100 pixels.
std::string transform_config(const std::string& transforms) {
    return "task: transform\n"
           "antialias: none\n"
           "resolution: {width: 100, height: 100}\n"
           "obj: two\n"
           "camera: {pos: [0, 0, 5], lookAt: [0, 0, 0], up: [0, 1, 0], width: 0.2, height: 0.2, nearClip: 0.1, "
           "farClip: 100}\n"
           "transforms:\n" +
           transforms;
}

TEST(Seed000, transformTaskGivesEachObjectItsOwnTransform) {
    TempDir dir;
    dir.write("two.obj", kTwoObjectsObj);
    const fs::path config = dir.write(
        "cfg.yaml", transform_config("  - {rotation: [1, 0, 0, 0], translation: [0, 0, 0], scale: [1, 1, 1]}\n"
                                     "  - {rotation: [1, 0, 0, 0], translation: [2, 0, 0], scale: [1, 1, 1]}\n"));
    ASSERT_EQ(run_raster({"render", config.string(), "-o", (dir / "out.ppm").string()}).status, 0);
    const Pixels image = read_pnm(dir / "out.ppm");
    // The second object's origin at (2, 0, 0) is 5 in front of the camera: NDC x = 2 / 5, pixel x = 50 * 1.4.
    EXPECT_EQ(image.at(50, 50)[0], 255);
    EXPECT_EQ(image.at(70, 50)[0], 255);
    EXPECT_EQ(image.at(30, 50)[0], 0);
}

TEST(Seed000, transformCountDifferentFromObjectCountWarnsAndDrawsTheRestUntransformed) {
    TempDir dir;
    dir.write("two.obj", kTwoObjectsObj);
    const fs::path config =
        dir.write("cfg.yaml", transform_config("  - {rotation: [1, 0, 0, 0], translation: [0, 0, 0], scale: 1}\n"));
    testing::internal::CaptureStderr();
    const CliResult result = run_raster({"render", config.string(), "-o", (dir / "out.ppm").string()});
    const std::string warning = testing::internal::GetCapturedStderr();
    ASSERT_EQ(result.status, 0) << result.err;
    EXPECT_TRUE(contains(warning, "warning"));
    EXPECT_TRUE(contains(warning, "2 object(s)"));
    const Pixels image = read_pnm(dir / "out.ppm");
    EXPECT_EQ(image.at(50, 50)[0], 255);
    EXPECT_EQ(image.at(70, 50)[0], 0);
}

// ---- shading-depth ----

// Quaternion (w, x, y, z), normalised, applied to v: v + 2w (q x v) + 2 q x (q x v).
glm::dvec3 rotate(glm::dvec4 wxyz, glm::dvec3 v) {
    wxyz /= glm::length(wxyz);
    const glm::dvec3 q(wxyz.y, wxyz.z, wxyz.w);
    return v + 2.0 * wxyz.x * glm::cross(q, v) + 2.0 * glm::cross(q, glm::cross(q, v));
}

TEST(Seed000, shadingDepthNearestPixelIsTheCubesNearestCorner) {
    TempDir dir;
    dir.copy_corpus("seeds/000");
    const CliResult result = run_raster({"render", (dir / "test-shading-depth.yaml").string(), "-o",
                                         (dir / "depth.ppm").string()});
    ASSERT_EQ(result.status, 0) << result.err;
    const Pixels depth = read_pnm(dir / "depth.ppm");
    ASSERT_EQ(depth.channels, 1);

    // The config's camera and cube (side 1, rotated by the first transform). Of a convex solid, a corner is
    // nearest to the camera; the camera looks from (0, 1, 2) at the origin with a 90 degree view.
    const glm::dvec3 eye(0, 1, 2), target(0, 0, 0), up(0, 2, -1);
    const glm::dvec3 w = glm::normalize(eye - target), u = glm::normalize(glm::cross(up, w)), v = glm::cross(w, u);
    double nearest = 1e9, second = 1e9;
    glm::dvec2 nearest_pixel(0.0);
    for (int corner = 0; corner < 8; ++corner) {
        const glm::dvec3 p = rotate({0.886, 0.0897, 0.3455, 0.2958},
                                    {corner & 1 ? 0.5 : -0.5, corner & 2 ? 0.5 : -0.5, corner & 4 ? 0.5 : -0.5});
        const double distance = glm::dot(eye - p, w);  // view depth
        const double ndc_x = glm::dot(p - eye, u) / distance, ndc_y = glm::dot(p - eye, v) / distance;
        if (distance < nearest) {
            second = nearest;
            nearest = distance;
            nearest_pixel = {(ndc_x + 1.0) * 400.0, (1.0 - ndc_y) * 400.0};
        } else {
            second = std::min(second, distance);
        }
    }
    ASSERT_GT(second - nearest, 0.05);  // one corner is clearly nearest
    int brightest = 0;
    for (uint8_t value : depth.bytes) brightest = std::max<int>(brightest, value);
    EXPECT_EQ(brightest, 255);
    int at_brightest = 0;
    for (int py = 0; py < depth.height; ++py)
        for (int px = 0; px < depth.width; ++px)
            if (depth.at(px, py)[0] == brightest) {
                ++at_brightest;
                EXPECT_LT(glm::length(glm::dvec2(px + 0.5, py + 0.5) - nearest_pixel), 3.0) << px << ", " << py;
            }
    EXPECT_GT(at_brightest, 0);
    EXPECT_EQ(depth.at(0, 0)[0], 0);  // no surface: black
}

// ---- shading ----

// A square facing the camera, lit from the camera's position: at the image centre l = v = n, so the document's
// Blinn-Phong gives ambient + colour * intensity / r^2 * (n.l + (n.h)^e) = ambient + 2 colour / r^2 (0..255).
TEST(Seed000, shadingIsBlinnPhongWithInverseSquareAttenuation) {
    TempDir dir;
    dir.write("quad.obj",
              "v -3 -3 0\nv 3 -3 0\nv 3 3 0\nv -3 3 0\nvn 0 0 1\nf 1//1 2//1 3//1\nf 1//1 3//1 4//1\n");
    for (int distance : {2, 4}) {
        const std::string d = std::to_string(distance);
        const fs::path config = dir.write(
            "cfg.yaml", "task: shading\n"
                        "resolution: {width: 64, height: 64}\n"
                        "obj: quad\n"
                        "camera: {pos: [0, 0, " + d + "], lookAt: [0, 0, 0], up: [0, 1, 0], width: 0.2, height: 0.2, "
                        "nearClip: 0.1, farClip: 100}\n"
                        "transforms: [{}]\n"
                        "exponent: 4\n"
                        "ambient: [10, 10, 10]\n"
                        "lights: [{pos: [0, 0, " + d + "], intensity: 1, color: [96, 48, 16]}]\n");
        const CliResult result = run_raster({"render", config.string(), "-o", (dir / "out.ppm").string()});
        ASSERT_EQ(result.status, 0) << result.err;
        const Pixels image = read_pnm(dir / "out.ppm");
        const double r2 = distance * distance;
        const double expected[3] = {10 + 2 * 96 / r2, 10 + 2 * 48 / r2, 10 + 2 * 16 / r2};
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(image.at(32, 32)[c], expected[c], 1.0) << "distance " << d;
    }
}

TEST(Seed000, documentsShadingConfigRendersTheLitCubeOnBlack) {
    TempDir dir;
    dir.copy_corpus("seeds/000");
    const CliResult result = run_raster({"render", (dir / "test-shading.yaml").string(), "-o", (dir / "s.ppm").string()});
    ASSERT_EQ(result.status, 0) << result.err;
    const Pixels image = read_pnm(dir / "s.ppm");
    EXPECT_EQ(image.at(0, 0)[0] + image.at(0, 0)[1] + image.at(0, 0)[2], 0);
    // The cube covers the centre; every lit pixel has at least the ambient 10 in each channel.
    for (int c = 0; c < 3; ++c) EXPECT_GE(image.at(400, 400)[c], 10 - 1);
}

// ---- every example, unchanged ----

TEST(Seed000, documentsConfigsRunUnchangedAndWriteBesideThemselves) {
    for (const char* name : {"test-triangle", "test-transform", "test-shading", "test-shading-depth"}) {
        TempDir dir;
        dir.copy_corpus("seeds/000");
        const CliResult result = run_raster({"render", (dir / (std::string(name) + ".yaml")).string()});
        EXPECT_EQ(result.status, 0) << name << ": " << result.err;
        // `output: output` names output.png next to the config, whatever the current directory.
        EXPECT_TRUE(fs::exists(dir / "output.png")) << name;
    }
}

TEST(Seed000, intsAndFloatsAreBothNumbers) {
    TempDir dir;
    dir.write("two.obj", kTwoObjectsObj);
    const fs::path config = dir.write("cfg.yaml",
                                      "task: transform\n"
                                      "antialias: SSAA\n"
                                      "samples: 4.0\n"
                                      "resolution: {width: 20.0, height: 20}\n"
                                      "obj: two\n"
                                      "camera: {pos: [0, 0, 5], lookAt: [0, 0, 0], up: [0, 1, 0], width: 1, "
                                      "height: 1.0, nearClip: 1, farClip: 100}\n"
                                      "transforms:\n"
                                      "  - {rotation: [1, 0, 0, 0], translation: [0, 0, 0], scale: [1, 1, 1]}\n"
                                      "  - {rotation: [1.0, 0.0, 0.0, 0.0], translation: [1.5, 0, 0], scale: 1}\n");
    const CliResult result = run_raster({"render", config.string()});
    EXPECT_EQ(result.status, 0) << result.err;
    EXPECT_TRUE(fs::exists(dir / "output.png"));
}

// ---- bad input ----

struct BadConfig {
    std::string from, to;  // an edit of the document's transform config
    std::string where;     // file:line:col
    std::string message;
};

TEST(Seed000, badConfigsExitTwoNamingTheLineAndWriteNothing) {
    const std::vector<BadConfig> cases = {
        {"task: transform", "task: transforms", "cfg.yaml:1:7", "task must be"},
        {"samples: 16", "samples: 5", "cfg.yaml:3:10", "square"},
        {"antialias: SSAA", "antialias: MSAA", "cfg.yaml:2:12", "'none' or 'SSAA'"},
        {"farClip: 100.0", "farClip: 0.05", "cfg.yaml:16:14", "farClip must be greater"},
        {"nearClip: 0.1", "nearclip: 0.1", "cfg.yaml:15:5", "did you mean 'nearClip'"},
        {"width: 0.2", "width: 0.4", "cfg.yaml:13:12", "must equal resolution width / height"},
        {"obj: trig", "obj: missing", "cfg.yaml:7:6", "missing.obj"},
        {"translation: [2.0, 0.0, 0.0]", "translation: [2.0, x, 0.0]", "cfg.yaml:24:28", "must be a number"},
    };
    for (const BadConfig& bad : cases) {
        TempDir dir;
        dir.copy_corpus("seeds/000");
        const fs::path config = dir.write("cfg.yaml", replaced(read_text(dir / "test-transform.yaml"), bad.from, bad.to));
        const CliResult result = run_raster({"render", config.string()});
        EXPECT_EQ(result.status, 2) << bad.to;
        EXPECT_TRUE(contains(result.err, bad.where)) << bad.to;
        EXPECT_TRUE(contains(result.err, bad.message)) << bad.to;
        EXPECT_FALSE(fs::exists(dir / "output.png")) << bad.to;
    }
}

TEST(Seed000, loaderReportsTheFormatAndTheTasksScene) {
    SceneFormat format = SceneFormat::raster;
    const Scene scene = load_scene(corpus("seeds/000/test-transform.yaml"), &format);
    EXPECT_EQ(format, SceneFormat::seed000);
    ASSERT_EQ(scene.meshes.size(), 2u);  // trig.obj's two objects, each with its transform
    EXPECT_EQ(scene.settings.samples, 16);
    EXPECT_EQ(scene.settings.pattern, SamplePattern::grid);
    // Camera 0.2 x 0.2 at near 0.1: half-height 0.1 at distance 0.1, a 90 degree field of view.
    EXPECT_NEAR(scene.camera.fov_y_degrees, 90.0f, 1e-4f);
    const Scene shading = load_scene(corpus("seeds/000/test-shading.yaml"));
    EXPECT_EQ(shading.settings.samples, 1);  // the shading tasks discard antialias and samples
    ASSERT_EQ(shading.lights.size(), 2u);
    EXPECT_TRUE(shading.lights[1].attenuate);
    EXPECT_NEAR(shading.lights[1].color.y, 87.0f / 255.0f, 1e-6f);
}

}  // namespace
}  // namespace raster
