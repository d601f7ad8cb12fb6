// Polygon triangulation tests: area kept and triangles inside for convex and concave polygons, the quad rule
// tinyobjloader used, tilted and clockwise polygons, and degenerate ones still giving n - 2 triangles.
#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "raster/formats/polygon_triangulation.h"

namespace {

using raster::PolygonTriangle;
using raster::triangulate_polygon;

std::vector<PolygonTriangle> triangulated(const std::vector<glm::vec3>& corners) {
    std::vector<PolygonTriangle> triangles;
    triangulate_polygon(corners, triangles);
    return triangles;
}

std::vector<glm::vec3> in_xy(const std::vector<glm::vec2>& points) {
    std::vector<glm::vec3> corners;
    for (const glm::vec2& p : points) corners.emplace_back(p.x, p.y, 0.0f);
    return corners;
}

// The triangle's vector area: its normal, as long as twice its area.
glm::vec3 doubled_area(const std::vector<glm::vec3>& c, const PolygonTriangle& t) {
    return glm::cross(c[t[1]] - c[t[0]], c[t[2]] - c[t[0]]);
}

// Even-odd rule in the z = 0 plane; a point on an edge counts as inside.
bool inside_or_on(const std::vector<glm::vec3>& polygon, glm::vec2 p) {
    bool inside = false;
    for (size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
        const glm::vec2 a(polygon[i]), b(polygon[j]);
        const float cross = (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
        const bool on_segment = std::fabs(cross) < 1e-5f && p.x >= std::min(a.x, b.x) - 1e-5f &&
                                p.x <= std::max(a.x, b.x) + 1e-5f && p.y >= std::min(a.y, b.y) - 1e-5f &&
                                p.y <= std::max(a.y, b.y) + 1e-5f;
        if (on_segment) return true;
        if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x) inside = !inside;
    }
    return inside;
}

// n - 2 triangles of the polygon's own corners, each wound as the polygon is about `normal`, adding up to `area`
// and inside the polygon (centroid and edge midpoints), so that together they tile it. `flat` is the same polygon
// laid in z = 0, where "inside" is decided.
void expect_tiles(const std::vector<glm::vec3>& corners, const std::vector<glm::vec3>& flat, glm::vec3 normal,
                  float area) {
    const std::vector<PolygonTriangle> triangles = triangulated(corners);
    ASSERT_EQ(triangles.size(), corners.size() - 2);
    float total = 0.0f;
    for (const PolygonTriangle& t : triangles) {
        for (uint32_t k : t) ASSERT_LT(k, corners.size());
        const float along_normal = glm::dot(doubled_area(corners, t), normal);
        EXPECT_GT(along_normal, 0.0f) << "triangle " << t[0] << " " << t[1] << " " << t[2] << " is turned over";
        total += 0.5f * along_normal;
        const glm::vec2 a(flat[t[0]]), b(flat[t[1]]), c(flat[t[2]]);
        for (const glm::vec2 p : {(a + b + c) / 3.0f, (a + b) / 2.0f, (b + c) / 2.0f, (c + a) / 2.0f})
            EXPECT_TRUE(inside_or_on(flat, p)) << "triangle " << t[0] << " " << t[1] << " " << t[2] << " leaves it";
    }
    EXPECT_NEAR(total, area, 1e-4f);
}

void expect_tiles(const std::vector<glm::vec3>& polygon_in_xy, float area) {
    expect_tiles(polygon_in_xy, polygon_in_xy, glm::vec3(0, 0, 1), area);
}

// Two teeth on a 5 x 1 bar, each 1 wide and 2 tall: area 5 + 2 * 2 = 9, and the gaps between them are outside.
const std::vector<glm::vec3> kComb = in_xy({{0, 0}, {5, 0}, {5, 1}, {4, 1}, {4, 3}, {3, 3}, {3, 1},
                                            {2, 1}, {2, 3}, {1, 3}, {1, 1}, {0, 1}});

TEST(PolygonTriangulation, keepsATriangleAsItIs) {
    const auto triangles = triangulated(in_xy({{0, 0}, {1, 0}, {0, 1}}));
    ASSERT_EQ(triangles.size(), 1u);
    EXPECT_EQ(triangles[0], (PolygonTriangle{0, 1, 2}));
}

TEST(PolygonTriangulation, tilesConvexPolygons) {
    // Shoelace area of (0,0) (2,0) (3,1) (1,3) (-1,1): (0 + 2 + 8 + 4 + 0) / 2 = 7.
    expect_tiles(in_xy({{0, 0}, {2, 0}, {3, 1}, {1, 3}, {-1, 1}}), 7.0f);
    // A regular 12-gon of circumradius 1: 12 * sin(30 degrees) / 2 = 3.
    std::vector<glm::vec2> dodecagon;
    for (int i = 0; i < 12; ++i) dodecagon.emplace_back(std::cos(i * M_PI / 6), std::sin(i * M_PI / 6));
    expect_tiles(in_xy(dodecagon), 3.0f);
}

TEST(PolygonTriangulation, tilesConcavePolygons) {
    // A square with its top edge pushed down to (1, 0.5): 4 - (2 * 1.5) / 2 = 2.5.
    expect_tiles(in_xy({{0, 0}, {2, 0}, {2, 2}, {1, 0.5f}, {0, 2}}), 2.5f);
    expect_tiles(kComb, 9.0f);
    // An arrow: a 3 x 2 shaft and a head of base 4 and height 2, 6 + 4 = 10, reflex where they meet.
    expect_tiles(in_xy({{0, 1}, {3, 1}, {3, 0}, {5, 2}, {3, 4}, {3, 3}, {0, 3}}), 10.0f);
}

TEST(PolygonTriangulation, clipsInThePlaneOfATiltedPolygon) {
    // The comb turned about x and y so that it lies along no axis plane: its triangles still tile it.
    const glm::vec3 x(std::cos(M_PI / 4), 0, -std::sin(M_PI / 4));
    const glm::vec3 y0(0, std::cos(M_PI / 6), std::sin(M_PI / 6));
    const glm::vec3 y = glm::normalize(y0 - glm::dot(y0, x) * x);
    std::vector<glm::vec3> tilted;
    for (const glm::vec3& c : kComb) tilted.push_back(c.x * x + c.y * y + glm::vec3(7, -3, 2));
    expect_tiles(tilted, kComb, glm::cross(x, y), 9.0f);
}

TEST(PolygonTriangulation, keepsTheWindingOfAClockwisePolygon) {
    const std::vector<glm::vec3> clockwise(kComb.rbegin(), kComb.rend());
    expect_tiles(clockwise, clockwise, glm::vec3(0, 0, -1), 9.0f);
}

// tinyobjloader's quad rule: (0 1 2) (0 2 3) when |c2 - c0| < |c3 - c1|, else (0 1 3) (1 2 3).
TEST(PolygonTriangulation, splitsAQuadAlongItsShorterDiagonal) {
    const std::vector<PolygonTriangle> along02{{0, 1, 2}, {0, 2, 3}}, along13{{0, 1, 3}, {1, 2, 3}};
    EXPECT_EQ(triangulated(in_xy({{0, 0}, {1, -2}, {2, 0}, {1, 2}})), along02);  // diagonals 2 and 4
    EXPECT_EQ(triangulated(in_xy({{-2, 0}, {0, -1}, {2, 0}, {0, 1}})), along13);  // diagonals 4 and 2
    // A tie (the unit square's diagonals are equal) goes to 1-3.
    EXPECT_EQ(triangulated(in_xy({{0, 0}, {1, 0}, {1, 1}, {0, 1}})), along13);
    // Out of the plane too: corners 0 and 2 are 2 apart in z only, 1 and 3 are sqrt(8) apart.
    EXPECT_EQ(triangulated({{0, 0, 0}, {1, -1, 1}, {0, 0, 2}, {-1, 1, 1}}), along02);
}

TEST(PolygonTriangulation, splitsAConcaveQuadByTheSameRule) {
    // A dart with its reflex corner 3 at (1, 0.5): the 0-2 diagonal (length 1) is shorter but runs outside, and
    // the rule takes it anyway, as tinyobjloader did: the second triangle comes out clockwise.
    const std::vector<glm::vec3> dart = in_xy({{0, 0}, {4, 0.5f}, {0, 1}, {1, 0.5f}});
    const auto triangles = triangulated(dart);
    EXPECT_EQ(triangles, (std::vector<PolygonTriangle>{{0, 1, 2}, {0, 2, 3}}));
    EXPECT_LT(doubled_area(dart, triangles[1]).z, 0.0f);
}

TEST(PolygonTriangulation, fansADegeneratePolygonSoNoCornerIsLost) {
    const std::vector<PolygonTriangle> fan{{0, 1, 2}, {0, 2, 3}, {0, 3, 4}};
    EXPECT_EQ(triangulated(in_xy({{0, 0}, {1, 0}, {2, 0}, {3, 0}, {4, 0}})), fan);  // on one line
    EXPECT_EQ(triangulated(std::vector<glm::vec3>(5, glm::vec3(1, 2, 3))), fan);  // at one point
}

TEST(PolygonTriangulation, givesEveryCornerOfASelfIntersectingPolygonATriangle) {
    // A pentagram drawn as five corners, each edge crossing two others: no ear is clean, yet 3 triangles come out
    // and every corner is in one.
    std::vector<glm::vec2> star;
    for (int i = 0; i < 5; ++i) star.emplace_back(std::cos(i * 4 * M_PI / 5), std::sin(i * 4 * M_PI / 5));
    const auto triangles = triangulated(in_xy(star));
    ASSERT_EQ(triangles.size(), 3u);
    std::vector<bool> used(5, false);
    for (const PolygonTriangle& t : triangles)
        for (uint32_t k : t) used.at(k) = true;
    EXPECT_EQ(used, std::vector<bool>(5, true));
}

TEST(PolygonTriangulation, tilesALargeDeeplyConcavePolygon) {
    // 1024 corners (the OBJ limit) on a circle, every other one pulled in to a quarter of the radius: a star whose
    // 1024 slices (centre, corner i, corner i + 1) each have area 1 * 0.25 * sin(2 pi / 1024) / 2.
    std::vector<glm::vec2> star;
    for (int i = 0; i < 1024; ++i) {
        const double r = i % 2 == 0 ? 1.0 : 0.25, angle = 2 * M_PI * i / 1024;
        star.emplace_back(r * std::cos(angle), r * std::sin(angle));
    }
    expect_tiles(in_xy(star), static_cast<float>(1024 * 0.25 * std::sin(2 * M_PI / 1024) / 2));
}

}  // namespace
