// The precision model, part 8: how far raster's float shading inputs and arithmetic can be from the documented
// formula evaluated exactly, so the oracle's colour interval (shader.h) holds every colour a correct raster may
// write. Each bound is derived next to its constant; the interval arithmetic carries them through the formula.
#pragma once

#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "oracle/reference/interval.h"
#include "oracle/reference/model_precision.h"
#include "oracle/reference/precision.h"
#include "raster/scene/mesh.h"

namespace raster::oracle {

// ATTRIBUTES, per vertex (norms are 2-norms, |.| componentwise):
//  - world position float(M_f (p, 1)): four products and three sums per component, gamma_4 |M_f| |(p, 1)|, and
//    raster's float model matrix M_f is itself within model.bound of the exact one (model_precision.h):
//    bound |(p, 1)| more;
inline constexpr int kWorldPositionRoundings = 4;
glm::dvec3 raster_world_position_error(const ModelMatrixError& model, const glm::vec3& position);
//  - a file normal, normalize(float(N n)) with N = transpose(inverse(mat3(M))) in float. An entry of the inverse
//    is a 2x2 minor (a b - c d: 3 roundings of |a b| + |c d| =: A) times the reciprocal of the determinant (a
//    3-term sum of entry times minor: gamma_6 of its magnitude D, then the reciprocal and the product: 2 more):
//    |dN_ij| <= (gamma_4 A_ij + |minor_ij| gamma_8 D / |det|) / |det|, unbounded when gamma_8 D >= |det|. Then
//    the product with n (gamma_3 |N| |n|), and a unit vector moves by at most 2 |dv| / |v| plus its own
//    normalisation's gamma_5. The minors and D are taken over |M_f| = |M| + model.bound, the determinant at its
//    least, |det M| (1 - k)^3 (model_precision.h), and M_f's own distance from M moves the exact inverse by
//    inverse_input_error (model_precision.h) more;
inline constexpr int kMinorRoundings = 4;
inline constexpr int kDeterminantRoundings = 8;
inline constexpr int kNormalizeAttributeRoundings = 5;
inline constexpr int kCrossRoundingsForNormals = 2;
// The normal matrix's part, the same for every vertex of a mesh: N's entries, each one's error and the magnitude
// of raster's (entry[i][j] is row i, column j); `bounded` false where the determinant's noise reaches it.
struct NormalMatrixError {
    double entry[3][3] = {};
    double error[3][3] = {};
    double magnitude[3][3] = {};
    bool bounded = false;
};
NormalMatrixError raster_normal_matrix_error(const ModelMatrixError& model);
double raster_file_normal_error(const NormalMatrixError& normal_matrix, const glm::vec3& normal);
//  - a face normal normalize(cross(b - a, c - a)) from raster's float world positions (within their errors e of
//    exact): the edges (one difference each, plus the vertices' errors), the cross product (|de1| x| (|e2| + |de2|)
//    + |e1| x| |de2| + gamma_2 |e1| x| |e2|, x| the cross product with its two products added), and the unit
//    vector (2 |dc| / |c| + gamma_5). Where |dc| reaches |c| the direction is unknown (2): the face may even be
//    skipped as degenerate by one renderer and not the other.
double raster_face_normal_error(const glm::dvec3 world[3], const glm::dvec3 error[3]);
//  - an averaged normal: each face's unit normal as above; the sum over F faces (gamma_F of the sum of their
//    magnitudes, each at most sqrt 3); and the final normalisation (2 |ds| / |s| + gamma_5).
//    `faces` lists the vertex's faces as triples of vertex indices into `world` and `position_error`.
double raster_averaged_normal_error(const std::vector<glm::dvec3>& world, const std::vector<glm::dvec3>& position_error,
                                    const std::vector<TriangleIndices>& faces, uint32_t first_vertex);

// ARITHMETIC. The interval evaluation (shader.cpp) widens each intermediate value by the float error raster's
// evaluation of it can have, computed from the interval's own magnitude:
//  - a 3-term dot product of unit vectors: gamma_3 absolute (sum of |a_i b_i| <= |a| |b| = 1);
//  - a unit vector from a difference (to the light, to the eye): gamma_1 per component for the difference
//    relative to its operands, then gamma_5 for the normalisation (absolute, per component);
//  - an interpolated attribute sum_i b_i a_i: gamma_3 of sum_i |b_i| |a_i|;
//  - the light's radiance colour * intensity (/ r^2): gamma_3 relative; each lit term's product: gamma_2 more;
//  - the specular power: std::pow, or for integer exponents n <= 256 repeated squaring: at most 16 products,
//    gamma_16 relative;
//  - the sum of the ambient and the lights' terms (L + 1 positive terms): gamma_(L+1) relative;
//  - base * diffuse + specular: gamma_2 relative;
//  - the resolve: a sum of S colours and a division (gamma_(S+1) of the magnitudes).
inline constexpr int kDotRoundings = 3;
inline constexpr int kDifferenceRoundings = 1;
inline constexpr int kDirectionRoundings = 5;
inline constexpr int kInterpolationRoundings = 3;
inline constexpr int kRadianceRoundings = 3;
inline constexpr int kTermRoundings = 2;
inline constexpr int kPowerRoundings = 16;
inline constexpr int kCombineRoundings = 2;
//  - Gooch: t = 0.5 (1 + n.l) (2 roundings), alpha + t (beta - alpha) (3), times the diffuse (1), and the tones
//    highlight + t (y, y, 0) + (1 - t) (0, 0, b) (two products, 1 - t and two sums: 5), relative.
inline constexpr int kGoochTiltRoundings = 2;
inline constexpr int kGoochBlendRoundings = 3;
inline constexpr int kGoochToneRoundings = 5;

// raster's interpolation sum_i b_i v_i over boxes: gamma_3 of sum_i |b_i| |v_i| per component.
// Inline, as the few helpers below: the oracle's shading calls them a few hundred times per sample.
inline Interval3 float_interpolate(const Interval3& bary, const Interval3 values[3]) {
    Interval3 out = bary.x * values[0] + bary.y * values[1] + bary.z * values[2];
    for (int c = 0; c < 3; ++c) {
        double magnitude = 0.0;
        for (int i = 0; i < 3; ++i) magnitude += bary[i].magnitude() * values[i][c].magnitude();
        out[c] = out[c].widened(float_gamma(kInterpolationRoundings) * magnitude);
    }
    return out;
}

// `value` widened by k float roundings relative to its own magnitude.
inline Interval after_roundings(Interval value, int k) { return value.widened(float_gamma(k) * value.magnitude()); }
inline Interval3 after_roundings(const Interval3& value, int k) {
    return {after_roundings(value.x, k), after_roundings(value.y, k), after_roundings(value.z, k)};
}

// BYTES. raster writes a linear value v as floor(clamp(v, 0, 1) 255 + 0.5), evaluated in float (the product and
// the sum round: gamma_2 relative to 255.5); the oracle maps an interval [lo, hi], widened by that, through the same
// formula in double. The result is the range of bytes a correct raster may write. No further level is allowed: a
// writer that truncates instead of rounding is off by one level, and that must show.
inline constexpr int kByteRoundings = 2;
struct ByteRange {
    int lo = 0, hi = 0;
    bool contains(int byte) const { return lo <= byte && byte <= hi; }
};
// The byte of an exact value (the oracle's own image): the same formula in double.
inline int exact_byte(double linear) {
    if (!(linear > 0.0)) return 0;
    if (linear >= 1.0) return 255;
    return static_cast<int>(std::floor(linear * 255.0 + 0.5));
}
inline ByteRange byte_range(Interval linear) {
    const double slack = float_gamma(kByteRoundings) * 255.5 / 255.0;
    return {exact_byte(linear.lo - slack), exact_byte(linear.hi + slack)};
}

}  // namespace raster::oracle
