// The real implementation, the mutants' implementations and the backends, as values the properties take.
#include "properties/implementation.h"

#include <cstdlib>

namespace raster::properties {

const std::vector<Backend>& drawing_backends() {
    static const std::vector<Backend> list{
        {"reference", RasterPath::reference, false, false, 1},
        {"tiled_simd_hiz_2threads", RasterPath::tiled, true, true, 2},
        {"tiled_simd_nohiz_1thread", RasterPath::tiled, true, false, 1},
        {"tiled_portable_hiz_1thread", RasterPath::tiled, false, true, 1},
        {"tiled_portable_nohiz_2threads", RasterPath::tiled, false, false, 2},
    };
    return list;
}

const Backend& reference_backend() { return drawing_backends()[0]; }
const Backend& production_backend() { return drawing_backends()[1]; }

const Implementation& real_implementation() {
    static const Implementation real{"real", PipelineStages{}, mutants::BuildingBlocks{}, production_backend()};
    return real;
}

Implementation implementation_of(const mutants::Mutant& mutant) {
    const Backend& backend = mutant.path == RasterPath::reference ? reference_backend() : production_backend();
    return {mutant.name, mutant.stages, mutant.blocks, backend};
}

Implementation on_backend(const Implementation& impl, const Backend& backend) {
    Implementation copy = impl;
    copy.backend = backend;
    return copy;
}

const Implementation& implementation_under_test() {
    static const Implementation chosen = [] {
        const char* name = std::getenv("RASTER_PROPERTY_MUTANT");
        return name && *name ? implementation_of(mutants::mutant(name)) : real_implementation();
    }();
    return chosen;
}

}  // namespace raster::properties
