// Coverage properties: the tiling check on pairs through samples, fans around samples and single triangles.
#include "properties/coverage_properties.h"

#include "properties/generators.h"
#include "properties/tiling_check.h"

namespace raster::properties {

void check_shared_edge_samples_are_covered_exactly_once(const Implementation& impl) {
    check_tiling(impl, *pairs_sharing_an_edge_through_samples());
}

void check_a_shared_vertex_on_a_sample_is_covered_exactly_once(const Implementation& impl) {
    check_tiling(impl, *fans_around_a_sample());
}

void check_covered_samples_equal_the_exact_integer_reference(const Implementation& impl) {
    check_tiling(impl, *single_triangles());
}

}  // namespace raster::properties
