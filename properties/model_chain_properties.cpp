// The model transform chain seen in pixels: a scene file's one-triangle mesh with a scale-rotate-translate chain,
// loaded by the real loader and rendered, covers exactly the samples that the triangle moved by the chain in double
// (Rodrigues' formula written here) and projected by the documented camera covers, outside a derived edge band.
// The oracle takes each mesh's model matrix from the loaded scene, so this is the pixel check of the loader's
// chain: a chain composed in the wrong order, or a wrong rotation, moves the triangle.
#include <array>
#include <cmath>
#include <string>

#include <glm/geometric.hpp>

#include "properties/failure.h"
#include "properties/generators/primitives.h"
#include "properties/printing.h"
#include "properties/property_registry.h"
#include "properties/stage_driver.h"
#include "raster/compat/scene_loader.h"

namespace raster::properties {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kSide = 64;            // the frame, in pixels
constexpr double kEyeZ = 8.0;        // the camera at (0, 0, 8) looks at the origin, up +y
constexpr double kFovDegrees = 45.0;

// The scene's preamble: the frame, the camera and unlit shading (the check reads coverage only).
const char* const kPreamble =
    "image: {width: 64, height: 64}\n"
    "camera: {eye: [0, 0, 8], target: [0, 0, 0], up: [0, 1, 0], fov: 45, near: 1, far: 100}\n"
    "render: {shading: unlit}\n";

// How far a covered sample may sit from an edge of the exact projected triangle and still differ from it: each
// snapped vertex is within half a snap step (2^-9 px at the default 8 bits) of its float position in x and y, and
// the float transform chain (three 24-bit products on coordinates under 8 world units, then the projection) moves
// it by under 2^-12 px on this 64-pixel frame; an edge between two such vertices moves by at most their larger
// displacement, under sqrt(2) 2^-9 + 2^-12 px. Twice that, so the band is an over-estimate.
const double kEdgeBand = 2.0 * (std::sqrt(2.0) * std::ldexp(1.0, -9) + std::ldexp(1.0, -12));

struct ChainCase {
    ScaleRotateTranslate chain;
    std::array<glm::vec3, 3> triangle;
};

std::ostream& operator<<(std::ostream& os, const ChainCase& c) {
    return os << "ChainCase{scale " << literal(c.chain.scale) << ", rotate " << float_literal(c.chain.degrees)
              << " about " << literal(c.chain.axis) << ", translate " << literal(c.chain.offset) << ", triangle "
              << literal(c.triangle[0]) << " " << literal(c.triangle[1]) << " " << literal(c.triangle[2]) << "}";
}

// Scales of either sign from 0.4 to 1.6 per axis, any rotation about any axis, offsets that keep the triangle in
// view (its vertices stay within 4 world units of the origin, 4 to 12 units in front of the eye).
Gen<ChainCase> chain_cases() {
    return gen::exec([] {
        ChainCase c;
        for (int i = 0; i < 3; ++i) {
            const float magnitude = static_cast<float>(0.4 + 1.2 * unit());
            c.chain.scale[i] = coin() ? magnitude : -magnitude;
            c.chain.offset[i] = static_cast<float>(2.0 * unit() - 1.0);
        }
        c.chain.degrees = static_cast<float>(360.0 * unit() - 180.0);
        glm::vec3 axis;
        do {
            axis = glm::vec3(static_cast<float>(2.0 * unit() - 1.0), static_cast<float>(2.0 * unit() - 1.0),
                             static_cast<float>(2.0 * unit() - 1.0));
        } while (glm::dot(axis, axis) < 0.01f);
        c.chain.axis = axis;
        for (glm::vec3& v : c.triangle)
            v = glm::vec3(static_cast<float>(2.0 * unit() - 1.0), static_cast<float>(2.0 * unit() - 1.0),
                          static_cast<float>(unit() - 0.5));
        return c;
    });
}

// The chain in double: scale, then the rotation by Rodrigues' formula, then the offset.
glm::dvec3 moved(const ChainCase& c, const glm::vec3& object) {
    const glm::dvec3 p = glm::dvec3(object) * glm::dvec3(c.chain.scale);
    const glm::dvec3 k = glm::normalize(glm::dvec3(c.chain.axis));
    const double radians = static_cast<double>(c.chain.degrees) * kPi / 180.0;
    const double cosine = std::cos(radians), sine = std::sin(radians);
    const glm::dvec3 rotated = p * cosine + glm::cross(k, p) * sine + k * (glm::dot(k, p) * (1.0 - cosine));
    return rotated + glm::dvec3(c.chain.offset);
}

// The documented camera and viewport (conventions.h): view = world - eye, NDC = focal (x, y) / -z_view, screen
// x = (ndc_x + 1) W / 2, y = (1 - ndc_y) H / 2.
glm::dvec2 screen_of(const glm::dvec3& world) {
    const double focal = 1.0 / std::tan(kFovDegrees * kPi / 360.0);
    const double depth = kEyeZ - world.z;  // -z_view, over 4 here
    const double ndc_x = focal * world.x / depth, ndc_y = focal * world.y / depth;
    return {(ndc_x + 1.0) * 0.5 * kSide, (1.0 - ndc_y) * 0.5 * kSide};
}

// The signed distance of p from the line a -> b, positive on the triangle's inside for a counter-clockwise
// (on screen) vertex order.
double signed_distance(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& p) {
    const glm::dvec2 edge = b - a;
    const double length = glm::length(edge);
    return length > 0.0 ? (edge.x * (p.y - a.y) - edge.y * (p.x - a.x)) / length : 0.0;
}

}  // namespace

// With culling off, the loaded and rendered triangle covers a sample exactly when the exact one does, at every
// sample at least kEdgeBand from each of its edges.
RASTER_DRAWING_PROPERTY(ModelMatrix, sceneFileChainPlacesTheTriangleWhereTheChainSays) {
    const ChainCase c = *chain_cases();
    const Scene scene = parse_scene(scene_file_with_chain(c.chain, c.triangle, kPreamble), "chain.yaml");
    const RenderResult result = render_with(impl, scene);
    std::array<glm::dvec2, 3> screen;
    for (int i = 0; i < 3; ++i) screen[i] = screen_of(moved(c, c.triangle[i]));
    const double area2 = signed_distance(screen[0], screen[1], screen[2]) * glm::length(screen[1] - screen[0]);
    RC_PRE(std::fabs(area2) > 1.0);  // edge-on: nothing to compare
    if (area2 < 0.0) std::swap(screen[1], screen[2]);
    int judged = 0;
    for (int y = 0; y < kSide; ++y)
        for (int x = 0; x < kSide; ++x) {
            const glm::dvec2 sample(x + 0.5, y + 0.5);
            double nearest = 1e300;
            for (int i = 0; i < 3; ++i)
                nearest = std::min(nearest, signed_distance(screen[i], screen[(i + 1) % 3], sample));
            if (std::fabs(nearest) < kEdgeBand) continue;
            ++judged;
            const bool expected = nearest > 0.0;
            const bool drawn = result.visibility.triangle[result.visibility.index(x, y, 0)] != kNoTriangle;
            if (drawn != expected)
                fail_case("pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") is " +
                          (drawn ? "covered" : "not covered") + " but lies " + double_literal(std::fabs(nearest)) +
                          " px " + (expected ? "inside" : "outside") + " the chain's triangle");
        }
    RC_CLASSIFY(judged == kSide * kSide, "every sample judged");
}

}  // namespace raster::properties
