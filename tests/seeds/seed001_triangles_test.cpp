// Seed 001 part 2.1: the document's four triangle command lines cover their projected area on the grey background.
#include "raster/compat/scene_format_seed001.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "tests/support/seed001_test_support.h"
#include "tests/support/seed_test_support.h"

namespace raster {
namespace {

using namespace seed_test;

constexpr int kWidth = 640, kHeight = 480;  // balboa's 2.1 image

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

}  // namespace
}  // namespace raster
