// The reversed-Z precision bounds, each written out as depth_precision.h derives it.
#include "properties/depth_precision.h"

#include <cmath>

namespace raster::properties {
namespace {
constexpr double u = 1.0 / (1 << 24);
}

double reversed_z_depth(double w, double near, double far) { return near * (far - w) / (w * (far - near)); }

double depth_error_at_near(double near, double far) {
    return 2.0 * u * ((far + 2.0 * near) / (far - near) + 2.0);
}

double depth_error_at_far(double near, double far) { return std::ldexp(near / (far - near), -22); }

double interpolated_depth_error(double near, double far, double largest_vertex_depth) {
    return std::ldexp(near / (far - near) + largest_vertex_depth, -22);
}

}  // namespace raster::properties
