// Seed 001's section 4 JSON scenes: read as the format says, and rendered as a ray cast of the document's camera.
#include "raster/compat/scene_format_seed001.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "raster/core/errors.h"
#include "raster/compat/scene_loader.h"
#include "tests/support/seed001_test_support.h"
#include "tests/support/seed_test_support.h"

namespace raster {
namespace {

using namespace seed_test;

struct ColoredTriangle {
    glm::dvec3 p[3];
    glm::dvec3 color[3];
};

struct Seed001View {
    glm::dvec3 position, right, up, direction;  // eqs. (25) to (28)
    double s = 1.0, z_near = 1e-6;
    int width = 0, height = 0;
};

// Eqs. (18) to (21): v' = v_c + cos(t) v1 + sin(t) v2 about the unit axis a.
glm::dvec3 rotate_about(const glm::dvec3& v, double degrees, glm::dvec3 axis) {
    axis = glm::normalize(axis);
    const double t = degrees * M_PI / 180.0;
    const glm::dvec3 vc = glm::dot(v, axis) * axis, v1 = v - vc, v2 = glm::cross(axis, v1);
    return vc + std::cos(t) * v1 + std::sin(t) * v2;
}

glm::dvec3 transformed(glm::dvec3 p, const nlohmann::json& steps) {
    for (const auto& step : steps) {
        if (step.contains("rotate")) {
            const auto& r = step["rotate"];
            p = rotate_about(p, r[0], {r[1], r[2], r[3]});
        } else if (step.contains("scale")) {
            p *= glm::dvec3(step["scale"][0], step["scale"][1], step["scale"][2]);
        } else if (step.contains("translate")) {
            p += glm::dvec3(step["translate"][0], step["translate"][1], step["translate"][2]);
        } else {
            ADD_FAILURE() << "the test reads rotate, scale and translate: " << step.dump();
        }
    }
    return p;
}

// The section 4 scene, read with nlohmann::json (not raster's reader); PLY files in their ascii form.
std::vector<ColoredTriangle> read_scene(const fs::path& file, Seed001View& view) {
    const nlohmann::json scene = nlohmann::json::parse(read_text(file));
    const auto& camera = scene["camera"];
    view.width = camera["resolution"][0];
    view.height = camera["resolution"][1];
    view.s = camera.value("s", 1.0);
    view.z_near = camera.value("z_near", 1e-6);
    const auto& lookat = camera["transform"][0]["lookat"];
    view.position = {lookat["position"][0], lookat["position"][1], lookat["position"][2]};
    const glm::dvec3 target(lookat["target"][0], lookat["target"][1], lookat["target"][2]);
    const glm::dvec3 up(lookat["up"][0], lookat["up"][1], lookat["up"][2]);
    view.direction = glm::normalize(target - view.position);
    view.right = glm::normalize(glm::cross(view.direction, up));
    view.up = glm::cross(view.right, view.direction);

    std::vector<ColoredTriangle> triangles;
    for (const auto& object : scene["objects"]) {
        std::vector<double> vertices, colors;
        std::vector<int> faces;
        if (object.contains("filename")) {
            std::istringstream ply(read_text(file.parent_path() / object["filename"].get<std::string>()));
            int vertex_count = 0, face_count = 0;
            for (std::string line; std::getline(ply, line) && line != "end_header";) {
                const std::vector<std::string> w = words(line);
                if (w.size() == 3 && w[0] == "element") (w[1] == "vertex" ? vertex_count : face_count) = std::stoi(w[2]);
            }
            for (int i = 0; i < vertex_count; ++i) {
                double x, y, z, r, g, b;
                ply >> x >> y >> z >> r >> g >> b;
                vertices.insert(vertices.end(), {x, y, z});
                colors.insert(colors.end(), {r, g, b});
            }
            for (int i = 0; i < face_count; ++i) {
                int n, a, b, c;
                ply >> n >> a >> b >> c;
                faces.insert(faces.end(), {a, b, c});
            }
        } else {
            vertices = object["vertices"].get<std::vector<double>>();
            colors = object["vertex_colors"].get<std::vector<double>>();
            faces = object["faces"].get<std::vector<int>>();
        }
        for (size_t f = 0; f + 2 < faces.size(); f += 3) {
            ColoredTriangle t;
            for (int k = 0; k < 3; ++k) {
                const int v = faces[f + k];
                t.p[k] = transformed({vertices[3 * v], vertices[3 * v + 1], vertices[3 * v + 2]}, object["transform"]);
                t.color[k] = {colors[3 * v], colors[3 * v + 1], colors[3 * v + 2]};
            }
            triangles.push_back(t);
        }
    }
    return triangles;
}

struct Hit {
    int triangle = -1;
    glm::dvec3 color{0.0};
};

// Through screen point (x, y): the image plane point (eq. (2) inverted), a ray from the camera, the nearest
// triangle in front of the near plane (Moller-Trumbore), and the colour at its 3D barycentrics (eq. (15)).
Hit cast(const Seed001View& view, const std::vector<ColoredTriangle>& triangles, double x, double y) {
    const double a = double(view.width) / view.height;
    const double px = (2.0 * x / view.width - 1.0) * view.s * a, py = (1.0 - 2.0 * y / view.height) * view.s;
    const glm::dvec3 ray = px * view.right + py * view.up + view.direction;  // camera (px, py, -1): t is depth
    Hit hit;
    double nearest = 1e300;
    for (size_t i = 0; i < triangles.size(); ++i) {
        const ColoredTriangle& tri = triangles[i];
        const glm::dvec3 e1 = tri.p[1] - tri.p[0], e2 = tri.p[2] - tri.p[0], h = glm::cross(ray, e2);
        const double det = glm::dot(e1, h);
        if (std::fabs(det) < 1e-15) continue;
        const glm::dvec3 s = view.position - tri.p[0], q = glm::cross(s, e1);
        const double b1 = glm::dot(s, h) / det, b2 = glm::dot(ray, q) / det, t = glm::dot(e2, q) / det;
        if (b1 < 0 || b2 < 0 || b1 + b2 > 1 || t < view.z_near || t >= nearest) continue;
        nearest = t;
        hit.triangle = int(i);
        hit.color = (1 - b1 - b2) * tri.color[0] + b1 * tri.color[1] + b2 * tri.color[2];
    }
    return hit;
}

// Screen position of a world point, and the colour an affine (not perspective-correct) interpolation would give.
glm::dvec2 project(const Seed001View& view, const glm::dvec3& p) {
    const glm::dvec3 d = p - view.position;
    return to_screen({glm::dot(d, view.right), glm::dot(d, view.up), -glm::dot(d, view.direction)}, view.s, view.width,
                     view.height);
}

glm::dvec3 affine_color(const Seed001View& view, const ColoredTriangle& tri, double x, double y) {
    const glm::dvec2 a = project(view, tri.p[0]), b = project(view, tri.p[1]), c = project(view, tri.p[2]);
    const double total = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
    const double w1 = ((x - a.x) * (c.y - a.y) - (c.x - a.x) * (y - a.y)) / total;
    const double w2 = ((b.x - a.x) * (y - a.y) - (x - a.x) * (b.y - a.y)) / total;
    return (1 - w1 - w2) * tri.color[0] + w1 * tri.color[1] + w2 * tri.color[2];
}

int to_byte_expected(double value) { return int(std::lround(std::clamp(value, 0.0, 1.0) * 255.0)); }

struct RayCastComparison {
    int interior = 0, background = 0, affine_differs = 0;
    int mismatches = 0;
    std::string first_mismatches;  // the first few, for the failure message
};

// Renders `scene` with `raster ARGS... -o out.ppm` and compares every 4th pixel that the ray cast finds wholly
// inside one triangle (its 16 samples and 4 corners) or wholly empty.
RayCastComparison compare_with_ray_cast(const fs::path& scene, const std::vector<std::string>& args, double s_override = 0) {
    TempDir dir;
    std::vector<std::string> command = args;
    command.insert(command.end(), {"-o", (dir / "out.ppm").string()});
    const CliResult result = run_raster(command);
    EXPECT_EQ(result.status, 0) << result.err;
    const Pixels image = read_pnm(dir / "out.ppm");
    Seed001View view;
    const std::vector<ColoredTriangle> triangles = read_scene(scene, view);
    if (s_override > 0) view.s = s_override;
    EXPECT_EQ(image.width, view.width);
    EXPECT_EQ(image.height, view.height);
    RayCastComparison counts;
    for (int py = 2; py < view.height; py += 4)
        for (int px = 2; px < view.width; px += 4) {
            std::vector<Hit> hits;
            glm::dvec3 mean(0.0), affine(0.0);
            for (int j = 0; j < 4; ++j)
                for (int i = 0; i < 4; ++i) {  // the 4x4 grid at ((i + 0.5) / 4, (j + 0.5) / 4)
                    hits.push_back(cast(view, triangles, px + (i + 0.5) / 4, py + (j + 0.5) / 4));
                    mean += hits.back().color / 16.0;
                    if (hits.back().triangle >= 0)
                        affine += affine_color(view, triangles[hits.back().triangle], px + (i + 0.5) / 4,
                                               py + (j + 0.5) / 4) / 16.0;
                }
            for (int corner = 0; corner < 4; ++corner)
                hits.push_back(cast(view, triangles, px + (corner & 1), py + (corner >> 1)));
            const bool one_triangle = std::all_of(hits.begin(), hits.end(), [&](const Hit& h) {
                return h.triangle == hits[0].triangle;
            });
            if (!one_triangle) continue;
            const uint8_t* pixel = image.at(px, py);
            const bool empty = hits[0].triangle < 0;
            int expected[3];
            bool differs = false;
            for (int c = 0; c < 3; ++c) {
                expected[c] = empty ? kGrey : to_byte_expected(mean[c]);
                differs = differs || std::abs(to_byte_expected(affine[c]) - expected[c]) >= 3;
            }
            (empty ? counts.background : counts.interior) += 1;
            counts.affine_differs += !empty && differs;
            // Empty pixels are exactly the background; inside, the mean of 16 float colours may round either way.
            if (!same_color(pixel, expected, empty ? 0 : 1) && ++counts.mismatches <= 5) {
                std::ostringstream text;
                text << " (" << px << ", " << py << "): got " << int(pixel[0]) << ' ' << int(pixel[1]) << ' '
                     << int(pixel[2]) << ", ray cast " << expected[0] << ' ' << expected[1] << ' ' << expected[2] << ';';
                counts.first_mismatches += text.str();
            }
        }
    EXPECT_EQ(counts.mismatches, 0) << counts.first_mismatches;
    return counts;
}

TEST(Seed001, twoShapesSceneMatchesARayCastWithPerspectiveCorrectColours) {
    const fs::path scene = corpus("seeds/001/two_shapes.json");
    const RayCastComparison counts = compare_with_ray_cast(scene, {"balboa", "-hw", "2_4", scene.string()});
    EXPECT_GT(counts.interior, 300);
    EXPECT_GT(counts.background, 300);
    EXPECT_GT(counts.affine_differs, 20);  // an affine interpolation would fail this test
}

TEST(Seed001, tetrahedronPlySceneMatchesARayCastWithPerspectiveCorrectColours) {
    const fs::path scene = corpus("seeds/001/tetrahedron.json");
    const RayCastComparison counts = compare_with_ray_cast(scene, {"balboa", "-hw", "2_4", scene.string()});
    EXPECT_GT(counts.interior, 300);
    EXPECT_GT(counts.background, 300);
    EXPECT_GT(counts.affine_differs, 20);
}

TEST(Seed001, sFlagOverridesTheScenesS) {
    const fs::path scene = corpus("seeds/001/two_shapes.json");
    const RayCastComparison counts = compare_with_ray_cast(scene, {"balboa", "-hw", "2_4", scene.string(), "-s", "2"}, 2.0);
    EXPECT_GT(counts.interior, 100);
}

// ---- the scene format ----

TEST(Seed001, flatAndNestedArraysAndFaceColoursRead) {
    const Scene flat = parse_scene(R"({"camera": {"resolution": [8, 6]}, "objects": [{
        "vertices": [0, 0, -1, 1, 0, -1, 0, 1, -1, 1, 1, -1], "faces": [0, 1, 2, 1, 3, 2],
        "face_colors": [1, 0, 0, 0, 0, 1]}]})",
                                   "flat.json");
    const Scene nested = parse_scene(R"({"camera": {"resolution": [8, 6]}, "objects": [{
        "vertices": [[0, 0, -1], [1, 0, -1], [0, 1, -1], [1, 1, -1]], "faces": [[0, 1, 2], [1, 3, 2]],
        "face_colors": [[1, 0, 0], [0, 0, 1]]}]})",
                                     "nested.json");
    for (const Scene* scene : {&flat, &nested}) {
        ASSERT_EQ(scene->meshes.size(), 1u);
        const MeshData& mesh = *scene->meshes[0].data;
        ASSERT_EQ(mesh.triangles.size(), 2u);
        EXPECT_EQ(mesh.triangles[1].v[1], 3u);
        EXPECT_EQ(mesh.positions[3], glm::vec3(1, 1, -1));
        ASSERT_EQ(mesh.face_colors.size(), 2u);
        EXPECT_EQ(mesh.face_colors[1], glm::vec3(0, 0, 1));
        EXPECT_EQ(scene->settings.width, 8);
        EXPECT_EQ(scene->settings.background, glm::vec3(0.5f));
        EXPECT_EQ(scene->settings.samples, 16);
    }
}

TEST(Seed001, badSceneNamesLineAndColumn) {
    const std::string text =
        "{\"camera\": {\"s\": 1},\n"
        " \"objects\": [{\"vertices\": [0, 0, -1, 1, 0, -1, 0, 1, -1],\n"
        "              \"faces\": [0, 1, 3]}]}\n";
    try {
        parse_scene(text, "bad.json");
        FAIL() << "expected an InputError";
    } catch (const InputError& error) {
        EXPECT_EQ(error.line(), 3);
        EXPECT_EQ(error.column(), 31);
        EXPECT_TRUE(contains(error.message(), "face index"));
    }
}

}  // namespace
}  // namespace raster
