// The top-left fill rule properties against the real rasterizer, or RASTER_PROPERTY_MUTANT's bug (fill_rule_properties.h says what each checks and derives its bounds).
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "properties/fill_rule_properties.h"

namespace raster::properties {

RC_GTEST_PROP(FillRule, sharedEdgeSamplesBelongToTheTriangleRightOfOrBelowTheEdge, ()) { check_shared_edge_samples_belong_to_the_triangle_right_of_or_below_the_edge(implementation_under_test()); }

RC_GTEST_PROP(FillRule, ownershipChangesUnderMirrorsAndQuarterTurnsAsTheRuleSays, ()) { check_ownership_changes_under_mirrors_and_quarter_turns_as_the_rule_says(implementation_under_test()); }

}  // namespace raster::properties
