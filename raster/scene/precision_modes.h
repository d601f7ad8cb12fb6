// The speed/accuracy modes a scene or the command line can choose, their names, and the named presets.
#pragma once

#include <string>
#include <vector>

namespace raster {

// How edge functions are set up: exactly in 64-bit fixed point (watertight), or in 32-bit float (the classic
// float rasterizer: c = dy*x - dx*y rounded to 24 bits, so shared edges can crack or double).
enum class EdgeArithmetic { fixed, float32 };

// How barycentrics (and every attribute) are interpolated across a triangle.
enum class Interpolation { perspective, affine };

// What the depth test compares, per sample:
//  reversed_z  float d = z/w with near at 1 and far at 0 (precision where it is needed; the default);
//  float_z     float z/w with near at 0 and far at 1 (the OpenGL-style [0, 1] mapping: precision crowds at near);
//  fixed24     z/w with near at 0 and far at 1, quantised to 24 bits (a classic D24 buffer).
enum class DepthFormat { reversed_z, float_z, fixed24 };

// Side-plane clipping: every plane in clip space (full), or only near and far, with the side planes replaced by a
// guard band 4x the viewport in which triangles are rasterized unclipped (beyond it they are still clipped).
enum class Clipping { full, guard_band };

// Everything a precision mode chooses besides snap bits, samples and pattern (which RenderSettings holds).
struct PrecisionModes {
    EdgeArithmetic edges = EdgeArithmetic::fixed;
    Interpolation interpolation = Interpolation::perspective;
    DepthFormat depth = DepthFormat::reversed_z;
    Clipping clipping = Clipping::full;
    bool hierarchical_z = true;  // per-block farthest-depth culling in the tiled renderer (never changes a pixel)
};

// Whether edges, interpolation, depth and clipping are at their exact defaults (hierarchical Z, which never changes
// a pixel, is not read): what another rasterizer (the GL backend, a plugin), told none of raster's modes, runs under.
bool exact_precision(const PrecisionModes& modes);

const char* to_string(EdgeArithmetic v);  // "fixed" | "float"
const char* to_string(Interpolation v);   // "perspective" | "affine"
const char* to_string(DepthFormat v);     // "reversed-z" | "float" | "fixed24"
const char* to_string(Clipping v);        // "full" | "guard-band"
bool parse_edge_arithmetic(const std::string& name, EdgeArithmetic& out);
bool parse_interpolation(const std::string& name, Interpolation& out);
bool parse_depth_format(const std::string& name, DepthFormat& out);
bool parse_clipping(const std::string& name, Clipping& out);

// The accepted names, for help texts and error messages: "fixed, float".
std::string edge_arithmetic_names();
std::string interpolation_names();
std::string depth_format_names();
std::string clipping_names();

}  // namespace raster
