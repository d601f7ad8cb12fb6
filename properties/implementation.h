// The implementation a property checks: the pipeline's stages and the building blocks outside them, either the
// real ones or a mutant's, and the rasterizer configuration (backend) that drawing properties run them on.
#pragma once

#include <string>
#include <vector>

#include "raster/pipeline/stages.h"
#include "mutants/building_blocks.h"
#include "mutants/catalogue.h"

namespace raster::properties {

// Which rasterizer a drawing property runs, and how: the reference full-frame rasterizer, or the tiled production
// renderer (what `raster render` runs) with AVX2 or portable code, hierarchical Z on or off, on 1 or 2 threads.
struct Backend {
    std::string name;  // the gtest name suffix, e.g. "tiled_simd_hiz_2threads"
    RasterPath path = RasterPath::tiled;
    bool allow_simd = true;
    bool hierarchical_z = true;
    int threads = 1;
};

// The backends every drawing property runs on: the reference, then four tiled configurations that take every
// pair of values of any two of the axes SIMD x hierarchical Z x threads (a pairwise cover of the eight), the first
// of them the production default.
const std::vector<Backend>& drawing_backends();
const Backend& production_backend();  // tiled, AVX2 where the CPU has it, hierarchical Z, 2 threads
const Backend& reference_backend();   // the reference rasterizer, 1 thread

struct Implementation {
    std::string name;                // "real", or the mutant's bug name
    PipelineStages stages;           // what render() runs
    mutants::BuildingBlocks blocks;  // matrix builders and the loader's transform chain
    Backend backend = production_backend();  // what drawing properties rasterize and render with
};

// The real rasterizer: the default stages and blocks, on the production backend.
const Implementation& real_implementation();

// The real rasterizer with one mutant's faulty stage or block, on the backend that runs it (the reference for a
// mutant of reference_rasterize, else the production one).
Implementation implementation_of(const mutants::Mutant& mutant);

// The same implementation on another backend.
Implementation on_backend(const Implementation& impl, const Backend& backend);

// What the property gtests check: the real rasterizer, unless the environment variable RASTER_PROPERTY_MUTANT
// names a bug of the catalogue, then that mutant (to watch a property catch it, shrink it and print the
// counterexample and RapidCheck's reproduce string). Throws std::out_of_range for an unknown name.
const Implementation& implementation_under_test();

}  // namespace raster::properties
