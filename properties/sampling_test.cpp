// Sampling properties against the real rasterizer, or RASTER_PROPERTY_MUTANT's bug (sampling_properties.h says what each checks and derives its bounds).
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "properties/sampling_properties.h"

namespace raster::properties {

RC_GTEST_PROP(Sampling, gridCoverageConvergesToTheExactAreaWithinAPerimeterBound, ()) { check_grid_coverage_converges_to_the_exact_area_within_a_perimeter_bound(implementation_under_test()); }

RC_GTEST_PROP(Sampling, standardPatternsAreTheDocumentedPositions, ()) { check_standard_patterns_are_the_documented_positions(implementation_under_test()); }

}  // namespace raster::properties
