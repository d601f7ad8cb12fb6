// The shadow properties, on the production shadow maps (rendered by the implementation's stages on the backend):
// a point no occluder comes near, seen from the light, is never shadowed (no acne, at any resolution, filter or
// light height), and a point an occluder covers well inside its edges, well in front of it, always is. The
// reference is the property's own geometry in double: directions from the light and angles between them.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "properties/failure.h"
#include "properties/generators/primitives.h"
#include "properties/printing.h"
#include "properties/property_registry.h"
#include "properties/stage_driver.h"
#include "raster/shading/shadow_maps.h"
#include "raster/geometry/vertex_stage.h"

namespace raster::properties {

namespace {

// A floor y = 0 of half-size 20, a light above it, and 1 to 4 occluder triangles between them.
struct ShadowCase {
    Scene scene;
    std::vector<std::array<glm::dvec3, 3>> occluders;
};

ShadowCase shadow_case() {
    ShadowCase c;
    Scene& scene = c.scene;
    scene.path = "shadow property";
    scene.settings.shading = ShadingMode::blinn_phong;
    scene.settings.shadows.resolution = 1 << *rc::gen::inRange(6, 9);  // 64 .. 256
    scene.settings.shadows.pcf = 1 + 2 * *rc::gen::inRange(0, 3);
    const glm::vec3 light(static_cast<float>(signed_unit() * 4.0), static_cast<float>(log_uniform(0.5, 10.0)),
                          static_cast<float>(signed_unit() * 4.0));
    scene.lights.push_back({light, glm::vec3(1.0f), 1.0f, false, true});
    SceneMesh floor;
    mutable_data(floor).positions = {{-20, 0, -20}, {-20, 0, 20}, {20, 0, 20}, {20, 0, -20}};
    mutable_data(floor).triangles = {{{0, 1, 2}}, {{0, 2, 3}}};
    floor.source = "floor";
    scene.meshes.push_back(floor);
    const int count = *rc::gen::inRange(1, 5);
    for (int i = 0; i < count; ++i) {
        SceneMesh occluder;
        std::array<glm::dvec3, 3> corners;
        const glm::dvec3 centre(signed_unit() * 5.0, (0.15 + 0.45 * (signed_unit() * 0.5 + 0.5)) * light.y,
                                signed_unit() * 5.0);
        const double size = log_uniform(0.1, 1.0) * light.y;
        for (int k = 0; k < 3; ++k) {
            corners[k] = centre + size * glm::dvec3(signed_unit(), signed_unit() * 0.5, signed_unit());
            mutable_data(occluder).positions.push_back(glm::vec3(corners[k]));
            corners[k] = glm::dvec3(occluder.data->positions.back());  // what raster draws
        }
        mutable_data(occluder).triangles = {{{0, 1, 2}}};
        occluder.source = "occluder";
        scene.meshes.push_back(occluder);
        c.occluders.push_back(corners);
    }
    return c;
}

// The angle between two directions.
double angle(const glm::dvec3& a, const glm::dvec3& b) {
    return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

// The angular distance, seen from `light`, from direction `d` to the triangle's directions (0 inside), and the
// signed angular depth of `d` inside it (its distance to the nearest edge's great circle, positive inside).
struct AngularPlace {
    double outside = 0.0, inside = 0.0;
};
AngularPlace place(const glm::dvec3& light, const std::array<glm::dvec3, 3>& t, const glm::dvec3& d) {
    glm::dvec3 v[3];
    for (int k = 0; k < 3; ++k) v[k] = glm::normalize(t[k] - light);
    const glm::dvec3 u = glm::normalize(d);
    // The triangle's directions are the cone of v0, v1, v2: the intersection of the three half-spaces bounded by
    // the planes through the light and an edge, each on its opposite vertex's side.
    const double orientation = glm::dot(glm::cross(v[0], v[1]), v[2]) > 0.0 ? 1.0 : -1.0;
    double inside = std::numeric_limits<double>::infinity(), outside = std::numeric_limits<double>::infinity();
    bool within = true;
    for (int k = 0; k < 3; ++k) {
        const glm::dvec3 normal = orientation * glm::normalize(glm::cross(v[k], v[(k + 1) % 3]));
        const double side = std::asin(std::clamp(glm::dot(normal, u), -1.0, 1.0));  // to the great circle
        within = within && side >= 0.0;
        inside = std::min(inside, side);
        // The distance to the arc itself: to its great circle where the foot falls on the arc, else to an end.
        const glm::dvec3 foot = u - glm::dot(normal, u) * normal;
        const bool on_arc = glm::dot(glm::cross(v[k], foot), glm::cross(v[k], v[(k + 1) % 3])) >= 0.0 &&
                            glm::dot(glm::cross(foot, v[(k + 1) % 3]), glm::cross(v[k], v[(k + 1) % 3])) >= 0.0;
        outside = std::min(outside, on_arc ? std::fabs(side) : std::min(angle(u, v[k]), angle(u, v[(k + 1) % 3])));
    }
    return {within ? 0.0 : outside, within ? inside : 0.0};
}

// The distance from p to the nearest point of triangle t (Ericson, "Real-Time Collision Detection", 5.1.5).
double distance_to_triangle(const glm::dvec3& p, const std::array<glm::dvec3, 3>& t) {
    const glm::dvec3 &a = t[0], &b = t[1], &c = t[2];
    const glm::dvec3 ab = b - a, ac = c - a, ap = p - a;
    const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
    if (d1 <= 0 && d2 <= 0) return glm::length(p - a);
    const glm::dvec3 bp = p - b;
    const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
    if (d3 >= 0 && d4 <= d3) return glm::length(p - b);
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) return glm::length(p - (a + d1 / (d1 - d3) * ab));
    const glm::dvec3 cp = p - c;
    const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
    if (d6 >= 0 && d5 <= d6) return glm::length(p - c);
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) return glm::length(p - (a + d2 / (d2 - d6) * ac));
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) return glm::length(p - (b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b)));
    const double denominator = 1.0 / (va + vb + vc);
    return glm::length(p - (a + ab * (vb * denominator) + ac * (vc * denominator)));
}

std::string describe(const ShadowCase& c) {
    std::string text = "light " + literal(c.scene.lights[0].position) + ", " +
                       std::to_string(c.scene.settings.shadows.resolution) + " texels, pcf " +
                       std::to_string(c.scene.settings.shadows.pcf) + ", occluders";
    for (const auto& t : c.occluders)
        text += " [" + literal(glm::vec3(t[0])) + " " + literal(glm::vec3(t[1])) + " " + literal(glm::vec3(t[2])) + "]";
    return text;
}

}  // namespace

// The footprint's angle: the filter's taps are texel centres within pcf / 2 + 1/2 texels of the point on each face
// axis, so within sqrt(2) (pcf / 2 + 1/2) texels; a texel spans 2 / N of face coordinates, and a step in face
// coordinates turns the direction by at most as many radians. Half a texel more for the rasterizer's snap and the
// float face coordinates.
RASTER_DRAWING_PROPERTY(Shadow, aPointNoOccluderComesNearIsLitAndOneWellInsideAnOccluderIsShadowed) {
    ShadowCase c = shadow_case();
    const ShadowSettings& settings = c.scene.settings.shadows;
    const TransformedScene geometry = run_vertex_stage(c.scene, vertex_stage_needs(c.scene.settings.shading));
    const ShadowMaps maps = shadow_maps_with(impl, c.scene, geometry.world_position);
    const double footprint = (std::sqrt(2.0) * (settings.pcf / 2.0 + 0.5) + 0.5) * 2.0 / settings.resolution;
    const glm::dvec3 light(c.scene.lights[0].position);
    int lit = 0, shadowed = 0;
    for (int i = 0; i < 64; ++i) {
        // Half the points anywhere on the floor, half where the light sees a point well inside an occluder.
        glm::vec3 point(static_cast<float>(signed_unit() * 12.0), 0.0f, static_cast<float>(signed_unit() * 12.0));
        if (i % 2) {
            const auto& t = c.occluders[static_cast<size_t>(i / 2) % c.occluders.size()];
            const double a = 0.3 + 0.1 * signed_unit(), b = 0.3 + 0.1 * signed_unit();  // away from the edges
            const glm::dvec3 q = t[0] + a * (t[1] - t[0]) + b * (t[2] - t[0]);
            if (q.y < light.y - 1e-3) {
                const glm::dvec3 on_floor = light + (q - light) * (light.y / (light.y - q.y));
                if (std::fabs(on_floor.x) < 19.0 && std::fabs(on_floor.z) < 19.0)
                    point = glm::vec3(static_cast<float>(on_floor.x), 0.0f, static_cast<float>(on_floor.z));
            }
        }
        const glm::dvec3 d = glm::dvec3(point) - light;
        const double distance = glm::length(d);
        // An upper bound of raster's bias here (docs/shadows.md: the constant part and slope_bias times the floor
        // plane's drop over the filter's square, at most the depth), from the floor's normal (0, 1, 0) and the
        // face the direction falls in: the drop over face coordinates within k = pcf / N of the point's is at most
        // depth k a / (b - k a), a = |right.y| + |up.y| <= 1, b = |d.y| / depth.
        const double depth = std::max({std::fabs(d.x), std::fabs(d.y), std::fabs(d.z)});
        const double k = static_cast<double>(settings.pcf) / settings.resolution, b = std::fabs(d.y) / depth;
        const double drop = b > 2.0 * k ? std::min(depth, depth * k / (b - k)) : depth;
        const double bias = settings.bias * depth + settings.slope_bias * drop;
        // The face the direction falls in looks along its major axis; every tap of the filter reads that face.
        glm::dvec3 axis(0.0);
        const int major = std::fabs(d.x) >= std::fabs(d.y) && std::fabs(d.x) >= std::fabs(d.z) ? 0
                          : std::fabs(d.y) >= std::fabs(d.z)                                 ? 1
                                                                                             : 2;
        axis[major] = d[major] < 0.0 ? -1.0 : 1.0;
        bool clear = true, covered = false;
        for (const auto& t : c.occluders) {
            const AngularPlace where = place(light, t, d);
            const bool in_front = distance_to_triangle(light, t) < distance;
            if (in_front && where.outside <= footprint) clear = false;
            // Covered: the filter's every tap sees the occluder (its direction well inside), and every point of the
            // occluder lies nearer along the face's axis than the point's depth less the bias, with room for the
            // map's float depth.
            double farthest = -std::numeric_limits<double>::infinity();
            for (const glm::dvec3& corner : t) farthest = std::max(farthest, glm::dot(corner - light, axis));
            if (where.inside > footprint && farthest < depth - bias - 1e-4 * depth) covered = true;
        }
        const float visible = maps.visibility(0, point, glm::vec3(0.0f, 1.0f, 0.0f));
        if (clear) {
            ++lit;
            if (visible != 1.0f)
                fail_case("floor point " + literal(point) + " with no occluder within " + double_literal(footprint) +
                          " rad of its direction from the light has visibility " + double_literal(visible) + "; " +
                          describe(c));
        }
        if (covered) {
            ++shadowed;
            if (visible != 0.0f)
                fail_case("floor point " + literal(point) + " whose direction lies " + double_literal(footprint) +
                          " rad inside an occluder well in front of it has visibility " + double_literal(visible) + "; " +
                          describe(c));
        }
    }
    RC_CLASSIFY(shadowed > 0, "some points shadowed");
    RC_CLASSIFY(lit > 0, "some points clear");
}

}  // namespace raster::properties
