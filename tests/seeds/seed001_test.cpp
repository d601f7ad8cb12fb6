// Seed 001 (balboa): the document's four 2_1 command lines cover their projected triangles, the section 4 JSON
// scenes match a ray cast of the document's own camera model, near-plane crossings are clipped, and bad command
// lines exit 2. Expectations are computed here from the document's equations.
#include "raster/formats/scene_format_seed001.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "raster/core/errors.h"
#include "raster/formats/scene_loader.h"
#include "tests/support/seed_test_support.h"

namespace raster {
namespace {

using namespace seed_test;

constexpr int kWidth = 640, kHeight = 480;  // balboa's 2.1 image
constexpr uint8_t kGrey = 128;              // 0.5 * 255 = 127.5, rounded to nearest (half up)

std::vector<std::string> words(const std::string& line) {
    std::istringstream in(line);
    std::vector<std::string> out;
    for (std::string word; in >> word;) out.push_back(word);
    return out;
}

// The document's 2.1 command lines, as printed, without the leading "./balboa".
std::vector<std::vector<std::string>> documents_commands() {
    std::vector<std::vector<std::string>> commands;
    std::istringstream lines(read_text(corpus("seeds/001/hw_2_1_commands.txt")));
    for (std::string line; std::getline(lines, line);) {
        std::vector<std::string> args = words(line);
        if (args.empty()) continue;
        args.erase(args.begin());
        commands.push_back(args);
    }
    return commands;
}

// The values after `flag` in a command line.
std::vector<double> values(const std::vector<std::string>& args, const std::string& flag, int count) {
    const auto at = std::find(args.begin(), args.end(), flag);
    std::vector<double> out;
    for (int i = 1; i <= count; ++i) out.push_back(std::stod(*(at + i)));
    return out;
}

// Eq. (5) then eq. (2) and its y counterpart (y down): camera space to screen pixels.
glm::dvec2 to_screen(const glm::dvec3& p, double s, int width, int height) {
    const double a = double(width) / height;
    const double x = -p.x / p.z, y = -p.y / p.z;
    return {width * (x + s * a) / (2 * s * a), height * (s - y) / (2 * s)};
}

// Sutherland-Hodgman against the image rectangle, then the shoelace area.
std::vector<glm::dvec2> clip_to_image(std::vector<glm::dvec2> polygon, double width, double height) {
    auto clip = [&](auto inside, auto cross) {
        std::vector<glm::dvec2> out;
        for (size_t i = 0; i < polygon.size(); ++i) {
            const glm::dvec2 a = polygon[i], b = polygon[(i + 1) % polygon.size()];
            if (inside(a)) out.push_back(a);
            if (inside(a) != inside(b)) out.push_back(cross(a, b));
        }
        polygon = out;
    };
    auto at_x = [](double x) {
        return [x](glm::dvec2 a, glm::dvec2 b) { return glm::dvec2(x, a.y + (b.y - a.y) * (x - a.x) / (b.x - a.x)); };
    };
    auto at_y = [](double y) {
        return [y](glm::dvec2 a, glm::dvec2 b) { return glm::dvec2(a.x + (b.x - a.x) * (y - a.y) / (b.y - a.y), y); };
    };
    clip([](glm::dvec2 p) { return p.x >= 0; }, at_x(0));
    clip([&](glm::dvec2 p) { return p.x <= width; }, at_x(width));
    clip([](glm::dvec2 p) { return p.y >= 0; }, at_y(0));
    clip([&](glm::dvec2 p) { return p.y <= height; }, at_y(height));
    return polygon;
}

double area(const std::vector<glm::dvec2>& polygon) {
    double twice = 0.0;
    for (size_t i = 0; i < polygon.size(); ++i) {
        const glm::dvec2 a = polygon[i], b = polygon[(i + 1) % polygon.size()];
        twice += a.x * b.y - b.x * a.y;
    }
    return std::fabs(twice) / 2.0;
}

bool same_color(const uint8_t* pixel, const int expected[3], int tolerance) {
    for (int c = 0; c < 3; ++c)
        if (std::abs(int(pixel[c]) - expected[c]) > tolerance) return false;
    return true;
}

TEST(Seed001, documentsTriangleCommandsCoverTheirProjectedArea) {
    const auto commands = documents_commands();
    ASSERT_EQ(commands.size(), 4u);
    for (const auto& command : commands) {
        TempDir dir;
        std::vector<std::string> args = {"balboa"};
        args.insert(args.end(), command.begin(), command.end());
        args.insert(args.end(), {"-o", (dir / "out.ppm").string()});
        const CliResult result = run_raster(args);
        ASSERT_EQ(result.status, 0) << result.err;
        const Pixels image = read_pnm(dir / "out.ppm");
        ASSERT_EQ(image.width, kWidth);
        ASSERT_EQ(image.height, kHeight);

        const double s = values(command, "-s", 1)[0];
        std::vector<glm::dvec2> projected;
        for (const char* flag : {"-p0", "-p1", "-p2"}) {
            const std::vector<double> p = values(command, flag, 3);
            projected.push_back(to_screen({p[0], p[1], p[2]}, s, kWidth, kHeight));
        }
        const std::vector<glm::dvec2> visible = clip_to_image(projected, kWidth, kHeight);
        const double expected_area = area(visible);
        // Anti-aliasing band: only pixels an edge crosses can be partly covered (|dx| + |dy| + 2 per edge).
        double band = 0.0;
        for (size_t i = 0; i < visible.size(); ++i) {
            const glm::dvec2 d = visible[(i + 1) % visible.size()] - visible[i];
            band += std::fabs(d.x) + std::fabs(d.y) + 2.0;
        }
        const std::vector<double> rgb = values(command, "-color", 3);
        const int color[3] = {int(std::lround(rgb[0] * 255)), int(std::lround(rgb[1] * 255)), int(std::lround(rgb[2] * 255))};
        const int grey[3] = {kGrey, kGrey, kGrey};
        int full = 0, touched = 0;
        for (int y = 0; y < image.height; ++y)
            for (int x = 0; x < image.width; ++x) {
                full += same_color(image.at(x, y), color, 1);
                touched += !same_color(image.at(x, y), grey, 0);
            }
        EXPECT_NEAR(full, expected_area, band) << command[4];
        EXPECT_NEAR(touched, expected_area, band) << command[4];
        EXPECT_GT(expected_area, 4.0 * band);  // the check is not vacuous
        EXPECT_TRUE(same_color(image.at(0, 0), grey, 0) || same_color(image.at(image.width - 1, image.height - 1), grey, 0));
    }
}

TEST(Seed001, backgroundIsExactlyGrey128) {
    TempDir dir;
    std::vector<std::string> args = {"balboa"};
    const auto command = documents_commands().at(0);
    args.insert(args.end(), command.begin(), command.end());
    args.insert(args.end(), {"-o", (dir / "out.ppm").string()});
    ASSERT_EQ(run_raster(args).status, 0);
    const Pixels image = read_pnm(dir / "out.ppm");
    for (auto [x, y] : {std::pair{0, 0}, {639, 0}, {0, 479}, {639, 479}, {320, 470}})
        for (int c = 0; c < 3; ++c) EXPECT_EQ(image.at(x, y)[c], kGrey) << x << ", " << y;
}

// One vertex behind the camera: the document's baseline rejects the triangle, its bonus (and raster) clips it.
// Every point of this triangle in front of the camera has y <= 0, so the picture's upper half stays empty.
TEST(Seed001, nearCrossingTriangleIsClippedNotRejected) {
    TempDir dir;
    const CliResult result = run_raster({"balboa", "-hw", "2_1", "-s", "1", "-p0", "0", "0", "1", "-p1", "-1", "-1", "-2",
                                         "-p2", "1", "-1", "-2", "-color", "1", "0", "0", "-znear", "0.1", "-o",
                                         (dir / "out.ppm").string()});
    ASSERT_EQ(result.status, 0) << result.err;
    const Pixels image = read_pnm(dir / "out.ppm");
    // 0.1 p0 + 0.45 p1 + 0.45 p2 = (0, -0.9, -1.7) is on the triangle, in front of the camera.
    const glm::dvec2 inside = to_screen({0, -0.9, -1.7}, 1.0, kWidth, kHeight);
    const int red[3] = {255, 0, 0}, grey[3] = {kGrey, kGrey, kGrey};
    for (int dy = -3; dy <= 3; ++dy)
        for (int dx = -3; dx <= 3; ++dx)
            EXPECT_TRUE(same_color(image.at(int(inside.x) + dx, int(inside.y) + dy), red, 0));
    for (int y = 0; y < kHeight / 2 - 1; ++y)
        for (int x = 0; x < kWidth; x += 7) ASSERT_TRUE(same_color(image.at(x, y), grey, 0)) << x << ", " << y;
}

// ---- JSON scenes: a ray cast of the document's camera model ----

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

TEST(Seed001, renderReadsTheSameSceneAsBalboaAndParts22And23TakeSceneFiles) {
    TempDir dir;
    const std::string scene = corpus("seeds/001/two_shapes.json").string();
    ASSERT_EQ(run_raster({"balboa", "-hw", "2_4", scene, "-o", (dir / "b.ppm").string()}).status, 0);
    ASSERT_EQ(run_raster({"render", scene, "-o", (dir / "r.ppm").string()}).status, 0);
    ASSERT_EQ(run_raster({"balboa", "-hw", "2_3", scene, "-o", (dir / "b3.ppm").string()}).status, 0);
    EXPECT_EQ(read_text(dir / "b.ppm"), read_text(dir / "r.ppm"));
    EXPECT_EQ(read_text(dir / "b.ppm"), read_text(dir / "b3.ppm"));
}

TEST(Seed001, defaultOutputNamesFollowTheDocumentsSubmissionNames) {
    TempDir dir;
    const fs::path here = fs::current_path();
    fs::current_path(dir.path());
    const CliResult triangle = run_raster({"balboa", "-hw", "2_1", "-p0", "0", "0", "-1", "-p1", "1", "0", "-1", "-p2",
                                           "0", "1", "-1", "-color", "1", "1", "1"});
    const CliResult scene = run_raster({"balboa", "-hw", "2_4", corpus("seeds/001/tetrahedron.json").string()});
    fs::current_path(here);
    EXPECT_EQ(triangle.status, 0) << triangle.err;
    EXPECT_EQ(scene.status, 0) << scene.err;
    EXPECT_TRUE(fs::exists(dir / "hw_2_1.png"));
    EXPECT_TRUE(fs::exists(dir / "hw_2_4_tetrahedron.png"));
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
        const MeshData& mesh = scene->meshes[0].data;
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

// ---- the command line ----

struct BadCommand {
    std::vector<std::string> args;
    std::string message;
};

TEST(Seed001, badCommandLinesExitTwoWithAClearMessageAndWriteNothing) {
    const std::vector<std::string> triangle = {"-hw", "2_1", "-p0", "-1", "-1", "-3", "-p1", "0", "1", "-3",
                                               "-p2", "1", "-1", "-3", "-color", "0.7", "0.3", "0.4"};
    auto with = [&](std::vector<std::string> extra) {
        std::vector<std::string> args = triangle;
        args.insert(args.end(), extra.begin(), extra.end());
        return args;
    };
    const std::vector<BadCommand> cases = {
        {{"-hw", "2_1", "-p0", "1", "2"}, "-p0 needs 3 numbers (X Y Z), got 2"},
        {{"-hw", "2_1", "-p0", "1", "2", "-p1", "0", "0", "-1"}, "-p0 needs 3 numbers (X Y Z), got 2"},
        {{"-hw", "2_1", "-p0", "1", "x", "3"}, "-p0: 'x' is not a number"},
        {with({"-q"}), "unknown flag '-q'"},
        {with({"-s"}), "-s needs 1 number"},
        {with({"-znear", "0"}), "z_near must be > 0"},
        {with({"-s", "-2"}), "s must be a positive number"},
        {with({"-color", "1", "1", "1"}), "-color is given twice"},
        {{"-hw", "2_1", "-p0", "0", "0", "-1", "-p1", "1", "0", "-1", "-color", "1", "1", "1"}, "needs -p2"},
        {{"-p0", "0", "0", "-1"}, "missing -hw"},
        {{"-hw", "3_1"}, "2_1, 2_2, 2_3 and 2_4"},
        {{"-hw", "2_2", "-s", "1", "-znear", "1e-6", "-scene_id", "0"}, "-scene_id"},
        {{"-hw", "2_4"}, "needs a scene file"},
        {with({"scene.json"}), "takes no scene file"},
        {{"-hw", "2_4", "a.json", "b.json"}, "unexpected argument 'b.json'"},
        {{"-hw", "2_4", "missing.json"}, "missing.json"},
    };
    for (const BadCommand& bad : cases) {
        TempDir dir;
        std::vector<std::string> args = {"balboa"};
        args.insert(args.end(), bad.args.begin(), bad.args.end());
        args.insert(args.end(), {"-o", (dir / "out.png").string()});
        const CliResult result = run_raster(args);
        EXPECT_EQ(result.status, 2) << bad.message;
        EXPECT_TRUE(contains(result.err, "raster balboa: error:")) << bad.message;
        EXPECT_TRUE(contains(result.err, bad.message));
        EXPECT_FALSE(fs::exists(dir / "out.png")) << bad.message;
    }
}

TEST(Seed001, helpListsBalboasFlags) {
    for (const char* flag : {"-h", "--help"}) {
        const CliResult result = run_raster({"balboa", flag});
        EXPECT_EQ(result.status, 0);
        for (const char* word : {"-hw", "2_1", "2_4", "-p0", "-color", "-s S", "-znear", "-o", "640 x 480", "128"})
            EXPECT_TRUE(contains(result.out, word)) << flag;
    }
}

}  // namespace
}  // namespace raster
