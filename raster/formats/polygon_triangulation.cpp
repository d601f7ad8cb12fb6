// Polygon triangulation: the quad diagonal rule, ear clipping in the Newell plane, and the fan for what is left.
#include "raster/formats/polygon_triangulation.h"

#include <cmath>
#include <utility>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace raster {
namespace {

// The quad rule in float, term by term as tinyobjloader wrote it, so that a tie is a tie here too.
void split_quad(std::span<const glm::vec3> c, std::vector<PolygonTriangle>& out) {
    const float e02x = c[2].x - c[0].x, e02y = c[2].y - c[0].y, e02z = c[2].z - c[0].z;
    const float e13x = c[3].x - c[1].x, e13y = c[3].y - c[1].y, e13z = c[3].z - c[1].z;
    const float squared02 = e02x * e02x + e02y * e02y + e02z * e02z;
    const float squared13 = e13x * e13x + e13y * e13y + e13z * e13z;
    if (squared02 < squared13) {
        out.push_back({0, 1, 2});
        out.push_back({0, 2, 3});
    } else {
        out.push_back({0, 1, 3});
        out.push_back({1, 2, 3});
    }
}

// The polygon's corners in 2D coordinates of its own plane, counter-clockwise; empty when the Newell normal is zero.
std::vector<glm::dvec2> in_polygon_plane(std::span<const glm::vec3> corners) {
    glm::dvec3 normal(0.0);
    for (size_t i = 0; i < corners.size(); ++i) {
        const glm::dvec3 a(corners[i]), b(corners[(i + 1) % corners.size()]);
        normal += glm::dvec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
    }
    const double length = glm::length(normal);
    if (!(length > 0.0) || !std::isfinite(length)) return {};
    const glm::dvec3 w = normal / length;
    // u, v, w right-handed: a polygon counter-clockwise about w is counter-clockwise in (u, v).
    const glm::dvec3 axis = std::fabs(w.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    const glm::dvec3 u = glm::normalize(glm::cross(axis, w));
    const glm::dvec3 v = glm::cross(w, u);
    std::vector<glm::dvec2> plane;
    plane.reserve(corners.size());
    for (const glm::vec3& corner : corners) {
        const glm::dvec3 c(corner);
        plane.emplace_back(glm::dot(c, u), glm::dot(c, v));
    }
    return plane;
}

// Twice the signed area of (a, b, c): positive when c lies left of a -> b.
double turn(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c) {
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

// Ear clipping over a ring of the remaining corners. Each corner knows whether it turns strictly left ("convex")
// and whether it is an ear; clipping an ear changes only its two neighbours, so each step re-examines those two,
// and the whole polygon costs O(n^2) however hard its shape.
class EarClipper {
public:
    EarClipper(std::vector<glm::dvec2> points, std::vector<PolygonTriangle>& out)
        : p_(std::move(points)), n_(p_.size()), prev_(n_), next_(n_), convex_(n_), ear_(n_), out_(out) {
        for (uint32_t i = 0; i < n_; ++i) {
            prev_[i] = i == 0 ? static_cast<uint32_t>(n_ - 1) : i - 1;
            next_[i] = i + 1 == n_ ? 0 : i + 1;
        }
        for (uint32_t i = 0; i < n_; ++i) convex_[i] = turns_left(i);
        for (uint32_t i = 0; i < n_; ++i) ear_[i] = is_ear(i);
    }

    void run() {
        uint32_t at = 0;
        size_t remaining = n_, looked = 0;
        while (remaining > 3) {
            if (!ear_[at]) {
                at = next_[at];
                if (++looked < remaining) continue;
                fan_rest(at);  // a full round without an ear
                return;
            }
            const uint32_t before = prev_[at], after = next_[at];
            out_.push_back({before, at, after});
            next_[before] = after;
            prev_[after] = before;
            --remaining;
            for (uint32_t neighbour : {before, after}) convex_[neighbour] = turns_left(neighbour);
            for (uint32_t neighbour : {before, after}) ear_[neighbour] = is_ear(neighbour);
            at = after;
            looked = 0;
        }
        out_.push_back({prev_[at], at, next_[at]});
    }

private:
    bool turns_left(uint32_t i) const { return turn(p_[prev_[i]], p_[i], p_[next_[i]]) > 0.0; }

    bool is_ear(uint32_t i) const {
        if (!convex_[i]) return false;
        const uint32_t a = prev_[i], c = next_[i];
        const glm::dvec2 &pa = p_[a], &pb = p_[i], &pc = p_[c];
        for (uint32_t j = next_[c]; j != a; j = next_[j]) {
            if (convex_[j]) continue;
            const glm::dvec2& q = p_[j];
            if (q == pa || q == pb || q == pc) continue;
            if (turn(pa, pb, q) >= 0.0 && turn(pb, pc, q) >= 0.0 && turn(pc, pa, q) >= 0.0) return false;
        }
        return true;
    }

    void fan_rest(uint32_t first) {
        for (uint32_t k = next_[first]; next_[k] != first; k = next_[k]) out_.push_back({first, k, next_[k]});
    }

    std::vector<glm::dvec2> p_;
    size_t n_;
    std::vector<uint32_t> prev_, next_;
    std::vector<char> convex_, ear_;
    std::vector<PolygonTriangle>& out_;
};

}  // namespace

void triangulate_polygon(std::span<const glm::vec3> corners, std::vector<PolygonTriangle>& out) {
    if (corners.size() == 3) {
        out.push_back({0, 1, 2});
        return;
    }
    if (corners.size() == 4) {
        split_quad(corners, out);
        return;
    }
    std::vector<glm::dvec2> plane = in_polygon_plane(corners);
    if (plane.empty()) {
        for (uint32_t k = 1; k + 1 < corners.size(); ++k) out.push_back({0, k, k + 1});
        return;
    }
    EarClipper(std::move(plane), out).run();
}

}  // namespace raster
