// What each precision mode leaves unjudged, and why (the oracle's precision model, oracle/reference/precision.h).
#include "harness/comparison/judged_classes.h"

#include <utility>

namespace raster::harness {

JudgedClasses judged_classes(const PrecisionModes& modes) {
    JudgedClasses judged;
    // Leaves `what` unjudged, saying why.
    auto leave = [&judged](bool JudgedClasses::*what, std::string why) {
        judged.*what = false;
        judged.unjudged.push_back(std::move(why));
    };
    if (modes.edges == EdgeArithmetic::float32)
        leave(&JudgedClasses::visibility,
              "--edges float leaves visibility unjudged: float edge values move an edge by up to 2^-19 M^2 pixels at "
              "coordinates M, far beyond the oracle's snap radius, and shared edges crack or double by design");
    if (modes.clipping == Clipping::guard_band)
        leave(&JudgedClasses::visibility,
              "--clipping guard-band leaves visibility unjudged: raster snaps vertices beyond the viewport "
              "unclipped, and the oracle's radius, measured at vertices clipped to the viewport, does not bound "
              "their float error");
    if (modes.depth != DepthFormat::reversed_z)
        leave(&JudgedClasses::visibility, std::string("--depth-format ") + to_string(modes.depth) +
                                              " leaves visibility unjudged: its depth keys tie over steps of about "
                                              "2^-24 in z/w, far coarser than the oracle's reversed-Z tie bound");
    if (modes.interpolation == Interpolation::affine)
        leave(&JudgedClasses::interpolation,
              "--interpolation affine leaves barycentrics, depth and colour unjudged: the oracle interpolates "
              "perspective-correctly by definition (visibility stays judged: the depth test's z/w is not "
              "interpolated by the mode)");
    return judged;
}

}  // namespace raster::harness
