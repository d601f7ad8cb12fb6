// Seed 003: --shading switches flat, Gouraud and Phong on the document's JSON scenes (each checked against its
// lighting model at a known point), PPM output, and our own example scene ("myscene") with several meshes and lights.
#include <algorithm>
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "raster/compat/scene_loader.h"
#include "tests/support/seed_test_support.h"

namespace raster {
namespace {

using namespace seed_test;

// One triangle in the plane z = 0 (A = (-4, -4), B = (4, -4), C = (0, 4)) seen and lit from (0, 0, 3): the
// image centre looks at the origin, where the triangle's barycentrics are (1/4, 1/4, 1/2).
const char* kLitTriangleScene = R"({
  "eye": [0, 0, 3], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 60,
  "width": 64, "height": 64, "near": -0.1, "far": -100,
  "lights": [{"position": [0, 0, 3], "color": [1, 1, 1]}],
  "meshes": [{"obj": "tri.obj", "ambient": [0.1, 0.1, 0.1], "diffuse": [0.3, 0.3, 0.3],
              "specular": [0.5, 0.5, 0.5], "phong_exponent": 50}]
})";

Pixels render_lit_triangle(const TempDir& dir, const std::string& shading) {
    dir.write("tri.obj", "v -4 -4 0\nv 4 -4 0\nv 0 4 0\nf 1 2 3\n");
    const fs::path scene = dir.write("scene.json", kLitTriangleScene);
    const fs::path out = dir / (shading + ".ppm");
    const CliResult result = run_raster({"render", scene.string(), "--shading", shading, "-o", out.string()});
    EXPECT_EQ(result.status, 0) << result.err;
    return read_pnm(out);
}

// ambient + diffuse (n.l) + specular lobe^e, with the eye and the light at the same point (so h = l and r.v = 2(n.l)^2 - 1).
double lit(double n_dot_l, double lobe) { return 0.1 + 0.3 * n_dot_l + 0.5 * std::pow(std::max(0.0, lobe), 50.0); }

// n.l at plane point (x, y, 0) for the light at (0, 0, 3); the normal is +z.
double n_dot_l(double x, double y) { return 3.0 / std::sqrt(x * x + y * y + 9.0); }

TEST(Seed003, shadingFlagSwitchesFlatGouraudAndPhong) {
    TempDir dir;
    // Pixel (32, 32) samples its centre (32.5, 32.5): NDC (1/64, -1/64), which a 60 degree view from distance 3
    // puts at plane point (x, y) = (1/64, -1/64) * tan(30) * 3.
    const double x = std::tan(M_PI / 6.0) * 3.0 / 64.0, y = -x;

    // Phong: per pixel, with the reflection vector's lobe r.v = 2 (n.l)^2 - 1.
    const double nl = n_dot_l(x, y);
    const Pixels phong = render_lit_triangle(dir, "phong");
    EXPECT_NEAR(phong.at(32, 32)[0], 255.0 * lit(nl, 2 * nl * nl - 1), 1.0);

    // Gouraud: lit at the vertices (n.l = 3/sqrt(41) at A and B, 3/5 at C; their highlights are below 1e-9), then
    // interpolated with the point's barycentrics. It misses the highlight (the document's written question 5).
    const double b2 = (y + 4.0) / 8.0, b1 = (1.0 - b2 + x / 4.0) / 2.0, b0 = 1.0 - b1 - b2;
    const double at_ab = n_dot_l(4, 4), at_c = n_dot_l(0, 4);
    const double gouraud_value = (b0 + b1) * lit(at_ab, at_ab) + b2 * lit(at_c, at_c);
    const Pixels gouraud = render_lit_triangle(dir, "gouraud");
    EXPECT_NEAR(gouraud.at(32, 32)[0], 255.0 * gouraud_value, 1.0);
    EXPECT_LT(gouraud.at(32, 32)[0] + 100, phong.at(32, 32)[0]);

    // Flat: one colour for the whole triangle, lit at its centroid (0, -4/3, 0) with the face normal.
    const double at_centroid = n_dot_l(0, -4.0 / 3.0);
    const Pixels flat = render_lit_triangle(dir, "flat");
    EXPECT_NEAR(flat.at(32, 32)[0], 255.0 * lit(at_centroid, at_centroid), 1.0);
    for (int py = 24; py < 40; ++py)
        for (int px = 24; px < 40; ++px) ASSERT_EQ(flat.at(px, py)[0], flat.at(32, 32)[0]) << px << ", " << py;
}

TEST(Seed003, ppmOutputIsBinaryP6OfTheScenesSize) {
    TempDir dir;
    const CliResult result =
        run_raster({"render", corpus("seeds/003/myscene.json").string(), "-o", (dir / "x.ppm").string()});
    ASSERT_EQ(result.status, 0) << result.err;
    const std::string bytes = read_text(dir / "x.ppm");
    const std::string header = "P6\n640 480\n255\n";
    EXPECT_EQ(bytes.substr(0, header.size()), header);
    EXPECT_EQ(bytes.size(), header.size() + 640u * 480u * 3u);
}

// The document asks for a scene of our own with a combination of objects and of lights, and its rendered PPM.
TEST(Seed003, mysceneHasSeveralMeshesAndLightsAndItsPpm) {
    SceneFormat format = SceneFormat::raster;
    const Scene scene = load_scene(corpus("seeds/003/myscene.json"), &format);
    EXPECT_EQ(format, SceneFormat::seed003);
    EXPECT_GE(scene.meshes.size(), 3u);
    EXPECT_GE(scene.lights.size(), 2u);
    const Pixels artefact = read_pnm(corpus("seeds/003/myscene.ppm"));
    EXPECT_EQ(artefact.channels, 3);
    EXPECT_EQ(artefact.width, scene.settings.width);
    EXPECT_EQ(artefact.height, scene.settings.height);
}

// The document's texture extra: an OBJ with texture coordinates whose material names a PPM image, and the PPM the
// scene renders to. (The oracle comparison of the scene is in tests/harness/compare_corpus_test.cpp.)
TEST(Seed003, texturedSceneTakesItsTextureFromTheObjsMaterialAndHasItsPpm) {
    const Scene scene = load_scene(corpus("seeds/003/textured.json"));
    ASSERT_EQ(scene.meshes.size(), 2u);
    const Material& crate = scene.meshes[1].material;
    ASSERT_TRUE(crate.texture.has_value());
    EXPECT_EQ(fs::path(crate.texture->path).filename(), "checker.ppm");
    EXPECT_EQ(crate.diffuse, glm::vec3(0.8f));  // the scene's coefficients, not the MTL's Kd 1
    EXPECT_EQ(scene.meshes[1].data->corner_uvs.size(), scene.meshes[1].data->triangles.size());
    EXPECT_TRUE(scene.meshes[0].data->corner_uvs.empty());  // the untextured floor keeps none
    const Pixels artefact = read_pnm(corpus("seeds/003/textured.ppm"));
    EXPECT_EQ(artefact.width, scene.settings.width);
    EXPECT_EQ(artefact.height, scene.settings.height);
}

}  // namespace
}  // namespace raster
