// The bug catalogue: classic rasterizer bugs (../shared/DESIGN.md, "Proving the checks can fail"), each a faulty
// variant of one stage or building block, plugged in through PipelineStages (and BuildingBlocks for the matrix
// builders and the loader's transform chain). Test code only. Every check must show which of them it catches.
#pragma once

#include <string>
#include <vector>

#include "raster/pipeline/frame.h"
#include "raster/pipeline/stages.h"
#include "mutants/building_blocks.h"

namespace raster::mutants {

struct Mutant {
    std::string name;       // the bug, as the design notes' catalogue names it
    std::string stage;      // the one stage it replaces
    std::string symptom;    // what the bug does, in a sentence
    PipelineStages stages;  // the real pipeline with that stage faulty
    BuildingBlocks blocks;  // the real building blocks, or with the faulty one when the bug lives in a block
    RasterPath path = RasterPath::tiled;  // the renderer that runs the faulty stage: reference for reference_rasterize
};

// Every faulty variant, in catalogue order. The list is built once.
const std::vector<Mutant>& catalogue();

// The mutant with this name; throws std::out_of_range when there is none.
const Mutant& mutant(const std::string& name);

}  // namespace raster::mutants
