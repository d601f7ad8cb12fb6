// What the oracle judges under a frame's precision modes: its precision model bounds raster's default arithmetic;
// a mode that moves raster beyond those bounds by design leaves what it moves unjudged, and says why.
#pragma once

#include <string>
#include <vector>

#include "raster/scene/precision_modes.h"

namespace raster::harness {

struct JudgedClasses {
    bool visibility = true;     // genuine visibility samples count
    bool interpolation = true;  // genuine barycentric and depth samples, and genuine colour pixels, count
    // One sentence per mode that leaves something unjudged: the mode, what it leaves, and why. Empty when every
    // class is judged.
    std::vector<std::string> unjudged;
};

// The classes the oracle judges under `modes` (docs/oracle.md, "Precision modes").
JudgedClasses judged_classes(const PrecisionModes& modes);

}  // namespace raster::harness
