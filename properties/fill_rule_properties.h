// The top-left fill rule: a sample on an edge shared by two triangles belongs to the one the rule names, and which
// one that is changes under mirrors and quarter turns of the scene exactly as the rule says.
#pragma once

#include <glm/vec2.hpp>

#include "properties/implementation.h"
#include "properties/reference/coverage_reference.h"

namespace raster::properties {

// The rule written as a nudge: a sample on an edge belongs to the triangle into which the sample moves when
// nudged by (e, e^2) for an infinitesimal e > 0 (right, then down; y down). For a non-horizontal edge that is the
// triangle to its right (the edge is that triangle's left edge); for a horizontal one the triangle below it (its
// top edge). Given the nudge's two directions, returns the side of line a-b it points to: the sign of
// orient(a, b, a + nudge), +1 or -1.
int side_the_rule_picks(reference::Point a, reference::Point b, glm::ivec2 first, glm::ivec2 second);

// Pairs sharing an edge through samples: each sample on the open edge is covered once, by the triangle the rule
// names.
void check_shared_edge_samples_belong_to_the_triangle_right_of_or_below_the_edge(const Implementation& impl);

// The same pair after a mirror or a quarter turn of the (square, symmetric-pattern) frame: the owner of each moved
// sample is the triangle the rule names in the moved scene, the original nudge carried back by the inverse map.
void check_ownership_changes_under_mirrors_and_quarter_turns_as_the_rule_says(const Implementation& impl);

}  // namespace raster::properties
