// The implementation a property checks: the pipeline's stages and the building blocks outside them, either the
// real ones or a mutant's, so every property can be run against every faulty variant of the bug catalogue.
#pragma once

#include <string>

#include "raster/pipeline/stages.h"
#include "mutants/building_blocks.h"
#include "mutants/catalogue.h"

namespace raster::properties {

struct Implementation {
    std::string name;                // "real", or the mutant's bug name
    PipelineStages stages;           // what render() runs
    mutants::BuildingBlocks blocks;  // matrix builders and the loader's transform chain
    RasterPath path = RasterPath::tiled;  // the renderer whole-scene properties render with
};

// The real rasterizer: the default stages and blocks.
const Implementation& real_implementation();

// The real rasterizer with one mutant's faulty stage or block.
Implementation implementation_of(const mutants::Mutant& mutant);

// What the property gtests check: the real rasterizer, unless the environment variable RASTER_PROPERTY_MUTANT
// names a bug of the catalogue, then that mutant (to watch a property catch it, shrink it and print the
// counterexample and RapidCheck's reproduce string). Throws std::out_of_range for an unknown name.
const Implementation& implementation_under_test();

}  // namespace raster::properties
