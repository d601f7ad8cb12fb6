// The precision model, part 9: textures. How far raster's texture lookups can be from the oracle's exact ones, so
// that the oracle's texture interval (texture_filters.h) holds every value a correct raster may read. Each bound
// is derived next to its constant.
#pragma once

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "oracle/reference/interval.h"

namespace raster::oracle {

// TEXELS. Level 0 is the float nearest code / 255 (or / 65535): within u of the exact value, relative. Each level
// below is computed in double from the float level above (weights summing to 1, so the error carries over) and
// rounded to float once: level k is within (k + 1) u of the oracle's exact chain, relative to the level's largest
// value.
inline constexpr int kTexelRoundingsAtLevelZero = 1;
double texel_error(int level, double magnitude);

// BILINEAR. The texel-space point x = u w (- 1/2) is computed in double from raster's float u (exact products
// well inside double, rounded at most twice: gamma_2 of |u w|, double); the fraction is rounded to float (u, which
// moves the value by u |b - a| <= 2u max); each glm::mix is x (1 - t) + y t, 4 roundings relative to the largest
// texel, and two levels of them nest: 8; so 10 roundings of the cell's largest texel in all.
inline constexpr int kBilinearRoundings = 10;
//  TRILINEAR adds its own mix of the two levels: 4 roundings of the larger.
inline constexpr int kLevelBlendRoundings = 4;
//  ANISOTROPIC: the tap offset (k + 1/2) / n - 1/2 (3 roundings), its product with the major axis and the sum with
//  uv (2 more): 5 roundings of |offset major| + |uv| on each tap's coordinates; the sum of n taps and the division
//  by n: gamma_(n + 1) of the sum of the taps' magnitudes.
inline constexpr int kTapCoordinateRoundings = 5;

// THE BARYCENTRICS' SUM. raster's barycentrics sum to 1 up to its rounding: each float component is rounded once from
// double (u |b_i|), and a clipped polygon's corner barycentrics come from float lerps, one per plane crossed (at most
// six, each 3 roundings of the corner's components): gamma_32 of sum |b_i| bounds |sum b - 1| with room to spare.
// The texture coordinates are then evaluated as uv_0 + b_1 (uv_1 - uv_0) + b_2 (uv_2 - uv_0) + (sum b - 1) uv_0,
// which, unlike sum b_i uv_i over independent boxes, does not multiply each box by the coordinates' distance from
// the texture's origin (a repeated texture far from it: thousands of texels).
inline constexpr int kBarycentricSumRoundings = 32;

// LEVEL OF DETAIL. raster's rho = |duv * size| in float: a product per component, two squares, a sum and a square
// root: 5 roundings, relative; log2 in float adds one rounding of its result (glibc's log2f is within 1 ulp), and
// the anisotropic ratio and quotient one rounding each.
inline constexpr int kRhoRoundings = 5;
inline constexpr int kLodRoundings = 2;

// THE DERIVATIVES raster uses (texture_lookup.h): g = W (c - b (1 . c)) with W = w . b and c a column of the
// inverse of M, the triangle's vertices in pixel-homogeneous coordinates, built in double from raster's float
// clip-space vertices. Those are within E (the clip error of precision.h section 2 and camera_precision.h) of the
// oracle's exact C, so raster's M is M + dM with |dM|_F <= the same errors scaled to pixels; then (first-order,
// with the second-order tail kept) column j of d(M^-1) = -M^-1 dM c_j is within |M^-1| |dM| |c_j| / (1 - k e)
// componentwise, k = |M|_F |M^-1|_F and e = |dM|_F / |M|_F, unbounded where k e >= 1/2; the columns are stored
// as floats (u more, relative). The barycentrics raster uses
// are anywhere in the sample's barycentric box (half-widths db); W and the products then add, per component i,
//   |dg_i| <= |W| (|dc_i| + db_i |s| + |b_i| |ds|) + |dW| |c_i - b_i s| + gamma_5 |W| (|c_i| + |b_i| |s|),
//   s = 1 . c, |ds| <= |dc|_1 + gamma_2 |c|_1, |dW| <= |w| . db + |dw| . |b| + gamma_3 |w| . |b|,
// and duv = sum_i g_i uv_i adds gamma_3 of sum_i |g_i| |uv_i|.
inline constexpr int kColumnRoundings = 1;
inline constexpr int kGradientRoundings = 5;  // with the footprint step's product
inline constexpr int kWeightRoundings = 3;
inline constexpr int kUvDerivativeRoundings = 3;

// The inputs of that bound for one triangle: its exact clip-space vertices, their errors, the image size.
struct DerivativeErrorInputs {
    glm::dvec4 clip[3];
    glm::dvec4 clip_error[3];
    int width = 0, height = 0;
};

// Per barycentric component, how far raster's dg/dx (x) and dg/dy (y) can be from the exact derivative at the
// exact barycentrics `bary` when raster's barycentrics are within `bary_error` of them. Infinite where the bound
// above is unbounded.
struct GradientError {
    glm::dvec3 x{0.0}, y{0.0};
};
GradientError gradient_error(const DerivativeErrorInputs& in, const glm::dvec3& bary, const glm::dvec3& bary_error);

}  // namespace raster::oracle
