// Fill-rule properties: a sample on an edge shared by two triangles belongs to the one the top-left rule names, and
// which one that is changes under mirrors and quarter turns of the scene exactly as the rule says. Owners of
// on-edge samples are checked against the rule written as a nudge, before and after mirroring or turning the scene.
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "properties/failure.h"
#include "properties/generators.h"
#include "properties/property_registry.h"
#include "properties/reference/coverage_reference.h"
#include "properties/tiling_check.h"

namespace raster::properties {
namespace {

using reference::orient;
using reference::Point;

// The rule written as a nudge: a sample on an edge belongs to the triangle into which the sample moves when
// nudged by (e, e^2) for an infinitesimal e > 0 (right, then down; y down). For a non-horizontal edge that is the
// triangle to its right (the edge is that triangle's left edge); for a horizontal one the triangle below it (its
// top edge). Given the nudge's two directions, returns the side of line a-b it points to: the sign of
// orient(a, b, a + nudge), +1 or -1.
int side_the_rule_picks(Point a, Point b, glm::ivec2 first, glm::ivec2 second) {
    const __int128 dx = b.x - a.x, dy = b.y - a.y;
    auto toward = [&](glm::ivec2 nudge) { return dx * nudge.y - dy * nudge.x; };  // orient(a, b, a + nudge)
    __int128 s = toward(first);
    if (s == 0) s = toward(second);
    return s > 0 ? 1 : -1;
}

// A sample exactly on the shared edge, and which triangle (0 holds C, 1 holds D) covered it.
struct EdgeSample {
    Point fixed;
    int owner;
};

// Draws the pair A B C / B A D and returns its samples on the open edge A-B, failing unless each is covered by
// exactly one triangle, the one on the side the rule picks for the nudge (first, then second).
std::vector<EdgeSample> owners_on_the_shared_edge(const Implementation& impl, const TilingCase& c, glm::ivec2 first,
                                                  glm::ivec2 second) {
    const Frame& frame = c.frame;
    const std::vector<uint32_t> owners = coverage_owners(impl, frame, clip_triangles(frame, c.mesh));
    const std::vector<Point> v = snapped_vertices(frame, c.mesh);
    const Point a = v[0], b = v[1], with_c = v[2];
    const int side = side_the_rule_picks(a, b, first, second);
    const int expected = (orient(a, b, with_c) > 0 ? 1 : -1) == side ? 0 : 1;
    std::vector<EdgeSample> found;
    for (const Sample& s : samples_of(frame)) {
        if (!reference::on_open_segment(a, b, s.fixed)) continue;
        const uint32_t who = owners[s.index];
        if (who != (1u << expected))
            fail_case(describe(s) + " on the shared edge is covered by " +
                      (who == 0 ? std::string("neither triangle") : who == 3 ? std::string("both triangles")
                                                                            : "triangle " + std::to_string(who >> 1)) +
                      "; the rule gives it to triangle " + std::to_string(expected));
        found.push_back({s.fixed, expected});
    }
    if (found.empty()) fail_case("the generator promised samples on the shared edge, but none lies on it");
    return found;
}

}  // namespace

// Pairs sharing an edge through samples: each sample on the open edge is covered once, by the triangle the rule
// names.
RASTER_RENDERER_PROPERTY(FillRule, sharedEdgeSamplesBelongToTheTriangleRightOfOrBelowTheEdge) {
    const TilingCase c = *pairs_sharing_an_edge_through_samples();
    RC_CLASSIFY(true, c.kind);
    owners_on_the_shared_edge(impl, c, {1, 0}, {0, 1});
}

// The same pair after a mirror or a quarter turn of the (square, symmetric-pattern) frame: the owner of each moved
// sample is the triangle the rule names in the moved scene, the original nudge carried back by the inverse map.
RASTER_RENDERER_PROPERTY(FillRule, ownershipChangesUnderMirrorsAndQuarterTurnsAsTheRuleSays) {
    const TilingCase c = *symmetric_pairs_sharing_an_edge();
    const FrameSymmetry g = *rc::gen::elementOf(square_symmetries());
    RC_CLASSIFY(true, g.name);
    const std::vector<EdgeSample> before = owners_on_the_shared_edge(impl, c, {1, 0}, {0, 1});

    TilingCase moved = c;
    for (glm::dvec2& p : moved.mesh.vertices) p = apply(g, c.frame, p);
    // In the moved scene the rule nudges by (e, e^2); carried back by the inverse map (the transpose of a signed
    // permutation) that is L^T (1, 0) = (m0, m1) first, then L^T (0, 1) = (m2, m3), in the original scene.
    const std::vector<EdgeSample> after = owners_on_the_shared_edge(impl, moved, {1, 0}, {0, 1});
    const std::vector<Point> v = snapped_vertices(c.frame, c.mesh);
    const Point a = v[0], b = v[1], with_c = v[2];
    const int side = side_the_rule_picks(a, b, {g.m[0], g.m[1]}, {g.m[2], g.m[3]});
    const int predicted = (orient(a, b, with_c) > 0 ? 1 : -1) == side ? 0 : 1;

    // Every moved on-edge sample is the image of an original one (the pattern is symmetric), and vice versa.
    if (after.size() != before.size())
        fail_case(std::to_string(before.size()) + " samples on the edge before the " + g.name + ", " +
                  std::to_string(after.size()) + " after");
    for (const EdgeSample& s : after)
        if (s.owner != predicted)
            fail_case("after the " + g.name + " the owner is triangle " + std::to_string(s.owner) +
                      ", but the rule, carried back, predicts triangle " + std::to_string(predicted));
    RC_CLASSIFY(predicted != before.front().owner, "ownership changes");
    RC_CLASSIFY(predicted == before.front().owner, "ownership stays");
}

}  // namespace raster::properties
