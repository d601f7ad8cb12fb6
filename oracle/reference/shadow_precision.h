// The precision model, part 10: what raster's shadow lookup (docs/shadows.md) may read and compare for a shading
// point that raster's float arithmetic can place anywhere in a box. Each bound is derived next to its constant.
#pragma once

#include <vector>

#include <glm/vec3.hpp>

#include "oracle/reference/interval.h"
#include "raster/scene/scene.h"

namespace raster::oracle {

// THE DIRECTION. raster forms d = p - light in float (1 rounding per component, relative to |p| + |light|), picks
// the face from d (possible_faces), and takes the depth axis . d exactly (the axes are unit axis vectors: the
// products are by 0 or +-1 and the sums add zeros). s = right . d / depth and t = up . d / depth round once each
// (the division), and the face pixel x = (s + 1) N/2, y = (1 - t) N/2 twice more: gamma_3 of their magnitudes.
inline constexpr int kShadowDifferenceRoundings = 1;
inline constexpr int kShadowFaceCoordinateRoundings = 1;
inline constexpr int kShadowTexelRoundings = 2;
//
// THE TAPS. The filter reads the texels floor(x) + i, floor(y) + j for |i|, |j| <= pcf / 2, each clamped to the
// face; the map holds each texel's depth at its centre. The TAPS rectangle spans the centres of every texel raster
// may read: the map's answer depends on what covers those centres alone. The FOOTPRINT spans those texels whole and
// every position the point itself may have: where no occluder's edge crosses it, the taps see what the point's own
// direction sees.
//
// THE REFERENCE DEPTH depth - bias (docs/shadows.md): the receiver plane's depth along the direction of each
// corner of the filter's square, plane / (n . v_c), with v_c = axis + (s +- reach) right + (t +- reach) up: the
// corner coordinates round once (1), v_c is exact (each component is one of them or +-1), the dot products round
// 3 times relative to |n| |v_c| and |n| |d|, the ratio once and depth - ratio once; then the constant and slope
// terms (2 products and a sum: 2 roundings relative to their magnitudes) and the subtraction from depth (1). A
// corner whose n . v_c may have the other sign from n . d makes raster cap the drop at the depth, and the interval
// then holds that case too. n is the receiver's unit face normal with raster's error (the bias is a ratio, so the
// length of raster's unnormalised cross product does not matter).
inline constexpr int kShadowCornerRoundings = 1;
inline constexpr int kShadowDotRoundings = 3;
inline constexpr int kShadowBiasRoundings = 2;

// A rectangle of face pixels: x in [x0, x1], y in [y0, y1] (x right, y down, as a face image).
struct TexelRect {
    double x0 = 0, x1 = 0, y0 = 0, y1 = 0;
};

// One face raster may look the point up in.
struct ShadowLookup {
    int face = 0;
    Interval depth;       // the point's depth on the face, every value raster's float d may give
    Interval x, y;        // the point's own position on the face, in face pixels
    TexelRect taps;       // the centres of the texels the filter may read
    TexelRect footprint;  // those texels whole, and the point's positions
    Interval reference;   // depth - bias, every value raster may compare the map against
};

// Every face raster may use for a shading point in `position` (a box of world points holding raster's float
// point), with the receiver's unit face normal in the box `normal`; one lookup per face. Empty when the point may
// be at the light itself (raster then calls it lit: the caller must allow anything).
std::vector<ShadowLookup> shadow_lookups(const ShadowSettings& settings, const glm::dvec3& light,
                                         const Interval3& position, const Interval3& normal);

}  // namespace raster::oracle
