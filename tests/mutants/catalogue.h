// The bug catalogue: classic rasterizer bugs (DESIGN.md), each a faulty variant of one stage, living in the test
// tree and plugged into the real pipeline through PipelineStages. Every check must show which of them it catches.
#pragma once

#include <string>
#include <vector>

#include "raster/pipeline.h"

namespace raster::mutants {

struct Mutant {
    std::string name;       // the bug, as DESIGN.md's catalogue names it
    std::string stage;      // the one stage it replaces
    std::string symptom;    // what the bug does, in a sentence
    PipelineStages stages;  // the real pipeline with that stage faulty
};

// Every faulty variant, in catalogue order. The list is built once.
const std::vector<Mutant>& catalogue();

// The mutant with this name; throws std::out_of_range when there is none.
const Mutant& mutant(const std::string& name);

}  // namespace raster::mutants
