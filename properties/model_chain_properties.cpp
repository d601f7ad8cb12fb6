// The model transform chain seen in pixels: a scene file's one-triangle mesh with a scale-rotate-translate chain,
// loaded by the real loader and rendered, covers exactly the samples that the triangle moved by the chain in double
// (Rodrigues' formula written here) and projected by the documented camera covers, outside a derived edge band.
// The oracle takes each mesh's model matrix from the loaded scene, so this is the pixel check of the loader's
// chain: a chain composed in the wrong order, or a wrong rotation, moves the triangle.
#include <array>
#include <cmath>
#include <string>

#include <glm/geometric.hpp>

#include "properties/chain_reference.h"
#include "properties/failure.h"
#include "properties/generators/primitives.h"
#include "properties/printing.h"
#include "properties/property_registry.h"
#include "properties/stage_driver.h"
#include "raster/compat/scene_loader.h"

namespace raster::properties {
namespace {

constexpr int kSide = kChainFrameSide;

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

}  // namespace

// With culling off, the loaded and rendered triangle covers a sample exactly when the exact one does, at every
// sample at least kEdgeBand from each of its edges.
RASTER_DRAWING_PROPERTY(ModelMatrix, sceneFileChainPlacesTheTriangleWhereTheChainSays) {
    const ChainCase c = *chain_cases();
    const Scene scene = parse_scene(scene_file_with_chain(c.chain, c.triangle, kChainFramePreamble), "chain.yaml");
    const RenderResult result = render_with(impl, scene);
    std::array<glm::dvec2, 3> screen;
    for (int i = 0; i < 3; ++i) screen[i] = chain_frame_screen_of(chain_moved(c.chain, glm::dvec3(c.triangle[i])));
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
