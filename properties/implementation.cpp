// The real implementation and the mutants' implementations, as values the properties take.
#include "properties/implementation.h"

#include <cstdlib>

namespace raster::properties {

const Implementation& real_implementation() {
    static const Implementation real{"real", PipelineStages{}, mutants::BuildingBlocks{}, RasterPath::tiled};
    return real;
}

Implementation implementation_of(const mutants::Mutant& mutant) {
    return {mutant.name, mutant.stages, mutant.blocks, mutant.path};
}

const Implementation& implementation_under_test() {
    static const Implementation chosen = [] {
        const char* name = std::getenv("RASTER_PROPERTY_MUTANT");
        return name && *name ? implementation_of(mutants::mutant(name)) : real_implementation();
    }();
    return chosen;
}

}  // namespace raster::properties
