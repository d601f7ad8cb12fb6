// Instancing seen in pixels: a shape placed by several scene-graph nodes (each a chain, some under a parent that has
// its own), loaded by the real loader and rendered, covers exactly the samples that the same triangles cover when
// their vertices are moved in double (chain_reference.h) and written out flat as plain meshes, sample for sample and
// triangle for triangle, outside a derived edge band. A placement given another placement's transform, a child's
// chain applied after its parent's, or one copy of the shape moved by every node shows as pixels of the wrong
// triangle.
#include <array>
#include <cmath>
#include <string>
#include <vector>

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

// The model-chain property's band (model_chain_properties.cpp: half a snap step at each vertex, sqrt(2) 2^-9 px,
// plus the float chain's drift under 2^-12 px), with the drift doubled for a parent's chain after the node's
// (six float steps rather than three), and the flat copy's own rounding of each vertex to float (2^-24 of under 8
// world units, under 2^-16 px here) inside that. Twice the sum, an over-estimate.
const double kEdgeBand = 2.0 * (std::sqrt(2.0) * std::ldexp(1.0, -9) + std::ldexp(1.0, -11));

struct Placement {
    ScaleRotateTranslate node;
    bool has_parent = false;
    ScaleRotateTranslate parent;  // applied after the node's chain
};

struct InstancingCase {
    std::vector<std::array<glm::vec3, 3>> shape;  // 1 to 3 triangles in the shape's own coordinates
    std::vector<Placement> placements;            // 2 or 3
};

std::ostream& operator<<(std::ostream& os, const ScaleRotateTranslate& c) {
    return os << "{scale " << literal(c.scale) << ", rotate " << float_literal(c.degrees) << " about " << literal(c.axis)
              << ", translate " << literal(c.offset) << "}";
}

std::ostream& operator<<(std::ostream& os, const InstancingCase& c) {
    os << "InstancingCase{shape";
    for (const auto& t : c.shape) os << " [" << literal(t[0]) << " " << literal(t[1]) << " " << literal(t[2]) << "]";
    for (const Placement& p : c.placements) {
        os << ", node " << p.node;
        if (p.has_parent) os << " under " << p.parent;
    }
    return os << "}";
}

// A chain that keeps a shape within about 2.5 world units of the origin: scales of either sign from 0.5 to 1.2,
// any rotation, offsets up to 0.6 (a parent's are smaller still).
ScaleRotateTranslate random_chain(double reach) {
    ScaleRotateTranslate c;
    for (int i = 0; i < 3; ++i) {
        const float magnitude = static_cast<float>(0.5 + 0.7 * unit());
        c.scale[i] = coin() ? magnitude : -magnitude;
        c.offset[i] = static_cast<float>(reach * (2.0 * unit() - 1.0));
    }
    c.degrees = static_cast<float>(360.0 * unit() - 180.0);
    glm::vec3 axis;
    do {
        axis = glm::vec3(static_cast<float>(2.0 * unit() - 1.0), static_cast<float>(2.0 * unit() - 1.0),
                         static_cast<float>(2.0 * unit() - 1.0));
    } while (glm::dot(axis, axis) < 0.01f);
    c.axis = axis;
    return c;
}

Gen<InstancingCase> instancing_cases() {
    return gen::exec([] {
        InstancingCase c;
        c.shape.resize(1 + static_cast<size_t>(3.0 * unit() * 0.999));
        for (auto& t : c.shape)
            for (glm::vec3& v : t)
                v = glm::vec3(static_cast<float>(2.0 * unit() - 1.0), static_cast<float>(2.0 * unit() - 1.0),
                              static_cast<float>(unit() - 0.5));
        c.placements.resize(coin() ? 2 : 3);
        for (Placement& p : c.placements) {
            p.node = random_chain(0.6);
            p.has_parent = coin();
            if (p.has_parent) p.parent = random_chain(0.4);
        }
        return c;
    });
}

std::string steps(const ScaleRotateTranslate& c) {
    return "[{scale: " + yaml_vector(c.scale) + "}, {rotate: {angle: " + yaml_number(c.degrees) +
           ", axis: " + yaml_vector(c.axis) + "}}, {translate: " + yaml_vector(c.offset) + "}]";
}

// The shape as a scene-graph shape, each placement a node (under a parent node of its own where it has one).
std::string instanced_file(const InstancingCase& c) {
    std::string text = std::string(kChainFramePreamble) + "shapes:\n  piece:\n    vertices: [";
    for (size_t t = 0; t < c.shape.size(); ++t)
        for (int i = 0; i < 3; ++i) text += (t + i ? ", " : "") + yaml_vector(c.shape[t][i]);
    text += "]\n    faces: [";
    for (size_t t = 0; t < c.shape.size(); ++t)
        text += (t ? ", [" : "[") + std::to_string(3 * t) + ", " + std::to_string(3 * t + 1) + ", " +
                std::to_string(3 * t + 2) + "]";
    text += "]\nnodes:\n";
    for (const Placement& p : c.placements) {
        if (p.has_parent)
            text += "  - transform: " + steps(p.parent) + "\n    children:\n      - {shape: piece, transform: " +
                    steps(p.node) + "}\n";
        else
            text += "  - {shape: piece, transform: " + steps(p.node) + "}\n";
    }
    return text;
}

// Where a vertex of the shape lands under a placement, in double: the node's chain, then its parent's.
glm::dvec3 placed(const Placement& p, const glm::vec3& v) {
    const glm::dvec3 moved = chain_moved(p.node, glm::dvec3(v));
    return p.has_parent ? chain_moved(p.parent, moved) : moved;
}

// The same triangles moved in double and written flat: one plain mesh per placement, no transform.
std::string flat_file(const InstancingCase& c) {
    std::string text = std::string(kChainFramePreamble) + "meshes:\n";
    for (const Placement& p : c.placements) {
        text += "  - vertices: [";
        for (size_t t = 0; t < c.shape.size(); ++t)
            for (int i = 0; i < 3; ++i) text += (t + i ? ", " : "") + yaml_vector(glm::vec3(placed(p, c.shape[t][i])));
        text += "]\n    faces: [";
        for (size_t t = 0; t < c.shape.size(); ++t)
            text += (t ? ", [" : "[") + std::to_string(3 * t) + ", " + std::to_string(3 * t + 1) + ", " +
                    std::to_string(3 * t + 2) + "]";
        text += "]\n";
    }
    return text;
}

}  // namespace

// With culling off, at every sample at least kEdgeBand from every triangle's edge and inside at most one of them
// (where two overlap, which is in front is a depth question this property does not ask), the instanced scene and
// the flat one show the same triangle, or both none; and the one they show is the one whose moved copy covers the
// sample in double.
RASTER_DRAWING_PROPERTY(Instancing, aShapePlacedByNodesCoversTheSamplesOfItsTrianglesMovedAndWrittenFlat) {
    const InstancingCase c = *instancing_cases();
    const Scene instanced = parse_scene(instanced_file(c), "instanced.yaml");
    const Scene flat = parse_scene(flat_file(c), "flat.yaml");
    RC_ASSERT(instanced.meshes.size() == c.placements.size());
    for (const SceneMesh& mesh : instanced.meshes) RC_ASSERT(mesh.data == instanced.meshes.front().data);  // one copy
    const RenderResult drawn = render_with(impl, instanced);
    const RenderResult expected_drawn = render_with(impl, flat);
    // Every placed triangle on screen, in the scene's triangle order (placement by placement), counter-clockwise.
    std::vector<std::array<glm::dvec2, 3>> screen;
    for (const Placement& p : c.placements)
        for (const auto& t : c.shape) {
            std::array<glm::dvec2, 3> s;
            for (int i = 0; i < 3; ++i) s[i] = chain_frame_screen_of(placed(p, t[i]));
            if (signed_distance(s[0], s[1], s[2]) < 0.0) std::swap(s[1], s[2]);
            screen.push_back(s);
        }
    int judged = 0;
    for (int y = 0; y < kChainFrameSide; ++y)
        for (int x = 0; x < kChainFrameSide; ++x) {
            const glm::dvec2 sample(x + 0.5, y + 0.5);
            bool near_edge = false;
            int inside = 0;
            uint32_t covering = kNoTriangle;
            for (uint32_t id = 0; id < screen.size(); ++id) {
                double nearest = 1e300;
                for (int i = 0; i < 3; ++i)
                    nearest = std::min(nearest, signed_distance(screen[id][i], screen[id][(i + 1) % 3], sample));
                near_edge = near_edge || std::fabs(nearest) < kEdgeBand;
                if (nearest > 0.0) ++inside, covering = id;
            }
            if (near_edge || inside > 1) continue;
            ++judged;
            const size_t at = drawn.visibility.index(x, y, 0);
            const uint32_t got = drawn.visibility.triangle[at], flat_got = expected_drawn.visibility.triangle[at];
            if (got != flat_got || got != covering)
                fail_case("pixel (" + std::to_string(x) + ", " + std::to_string(y) + "): the instanced scene shows triangle " +
                          std::to_string(static_cast<int>(got)) + ", the flat one " +
                          std::to_string(static_cast<int>(flat_got)) + ", the moved triangles in double " +
                          std::to_string(static_cast<int>(covering)) + " (-1: none)");
        }
    RC_CLASSIFY(judged > kChainFrameSide * kChainFrameSide / 2, "most samples judged");
}

}  // namespace raster::properties
