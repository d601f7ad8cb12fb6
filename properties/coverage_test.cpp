// Coverage properties against the real rasterizer, or RASTER_PROPERTY_MUTANT's bug (coverage_properties.h says what each checks and derives its bounds).
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "properties/coverage_properties.h"

namespace raster::properties {

RC_GTEST_PROP(Coverage, sharedEdgeSamplesCoveredExactlyOnce, ()) { check_shared_edge_samples_are_covered_exactly_once(implementation_under_test()); }

RC_GTEST_PROP(Coverage, sharedVertexOnASampleCoveredExactlyOnce, ()) { check_a_shared_vertex_on_a_sample_is_covered_exactly_once(implementation_under_test()); }

RC_GTEST_PROP(Coverage, coveredSamplesEqualTheExactIntegerReference, ()) { check_covered_samples_equal_the_exact_integer_reference(implementation_under_test()); }

}  // namespace raster::properties
