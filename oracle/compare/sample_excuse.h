// Why a sample got its class, in figures: the quantity the classifier measured and the bound it held it to (an
// edge's distance against the band, two depth intervals against each other, a barycentric gap against its
// tolerance), for the report's pixel inspector. It explains the class sample_classifier.h gave; it does not decide it.
#pragma once

#include <string>

#include <glm/vec2.hpp>

#include "oracle/compare/sample_classifier.h"
#include "oracle/reference/reference_geometry.h"

namespace raster::oracle {

struct SampleExcuse {
    std::string rule;     // what was measured, naming the triangles: "edge band of triangle 12", "barycentric gap"
    bool has_figure = false;  // false where the rule is a yes or no (Embree's edge test, a grazed plane)
    double measured = 0;  // the figure, in the rule's unit (pixels, barycentric units, view depth, reversed z)
    double bound = 0;     // what the class allows it: ambiguous and agree samples have measured <= bound, genuine ones
                          // measured > bound
};

// The excuse for a sample of class `klass` at screen position `screen`, where raster saw `raster` and the oracle
// `oracle` (the arguments classify_sample took when it gave `klass`).
SampleExcuse sample_excuse(const ReferenceGeometry& reference, const glm::dvec2& screen, const SampleEntry& raster,
                           const SampleEntry& oracle, SampleClass klass);

}  // namespace raster::oracle
