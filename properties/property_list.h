// Every property of the suite as a value: its gtest suite and name and the check that runs it against any
// implementation. The gtests run each with the real implementation; the mutants run runs each against every bug.
#pragma once

#include <string>
#include <vector>

#include "properties/implementation.h"

namespace raster::properties {

struct Property {
    std::string suite;                        // the RC_GTEST_PROP suite, e.g. "Coverage"
    std::string name;                         // the RC_GTEST_PROP name, e.g. "sharedEdgeSamplesCoveredExactlyOnce"
    void (*check)(const Implementation&);     // draws its own cases with RapidCheck; fails through RC_ASSERT/fail_case
};

// The properties in the order the README lists them.
const std::vector<Property>& all_properties();

}  // namespace raster::properties
