// The precision model, part 2c: how far raster's float model matrix, composed from the scene's transform steps,
// can be from the oracle's exact one (model_transform.h), entry by entry; each bound is derived next to its
// constant. The vertex (precision.h section 2), world-position and normal bounds (shading_precision.h) add it.
#pragma once

#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "oracle/reference/camera.h"
#include "oracle/reference/camera_precision.h"
#include "raster/scene/model_transform.h"

namespace raster::oracle {

// RASTER'S STEPS, each a float matrix S_f with |S_f - S| <= E entrywise (S exact):
//  - translate, scale and matrix steps hold the file's floats: E = 0;
//  - rotate: Rodrigues' formula in double from the float angle and axis, rounded to float once per entry: u |S|
//    (plus u of double's error); double's error: the angle's conversion to radians (pi / 180 and the product:
//    3 roundings of |radians|, carried through sin and cos unchanged), sin and cos (1 ulp each) and the formula's
//    few products and sums on unit-sized values: at most (kRotateDoubleRoundings + 3 |radians|) 2^-53 per entry;
inline constexpr int kRotateDoubleRoundings = 32;
//  - quaternion: normalised in float (a 4-term dot product, the square root, the reciprocal and the scaling:
//    each component within gamma_5 of the unit quaternion, so |dq| <= gamma_5), then the entries 1 - 2 (y^2 + z^2)
//    and 2 (x y +- w z): each moves by at most 4 |q| |dq| + 2 |dq|^2 with q (every entry's gradient has norm at most
//    4 |q|), and its own arithmetic (products, a sum, 1 - s) adds gamma_3 of at most 3;
inline constexpr int kQuaternionNormalizeRoundings = 5;
inline constexpr int kQuaternionEntryRoundings = 3;
//  - look-at: raster's float basis, the camera's (camera_precision.h: right, up and back within E_right, E_up and
//    E_back in 2-norm, hence per entry), as the first three columns; the eye, a float, as the fourth: exact.
//
// RASTER'S PRODUCT P' = fl(S_f P_f): a 4-term dot product per entry, gamma_4 |S_f| |P_f|. With |P_f - P| <= B:
//     |P'_f - S P| <= |S| B + E |P| + E B + gamma_4 (|S| + E)(|P| + B)
// (plus double's own gamma_4 |S| |P| in the oracle's product).
inline constexpr int kProductRoundings = 4;
//
// RASTER'S INVERSE of the chain C (seed 001's camera), glm's cofactor inverse in float of C_f, |C_f - C| <= B_C:
//  - the input's error: inv(C_f) - inv(C) = -X dC inv(C_f), X = inv(C); with F = |X| B_C and k = ||F||_inf < 1,
//    |inv(C_f) - X| <= F |X| + k max(F |X|) / (1 - k) entrywise;
//  - the arithmetic: each cofactor a sum of three products of an entry and a 2 x 2 minor (a b - c d): 5 roundings
//    of A, the sum of its six |triple products| (the minor's permanent), and the determinant a 4-term dot product
//    of the first column with cofactors: 8 roundings of D, the permanent of |C_f|; then the reciprocal and the
//    product, 2 more. With |det C_f| >= |det C| (1 - k)^4 (each eigenvalue of I + X dC is at least 1 - k away
//    from 0):  |fl(inv) - inv(C_f)| <= (1 + gamma_2) (gamma_5 A + |inv| gamma_8 D) / (|det C_f| - gamma_8 D) +
//    gamma_2 |inv|, unbounded when gamma_8 D reaches |det C_f|.
inline constexpr int kCofactorRoundings = 5;
inline constexpr int kInverseDeterminantRoundings = 8;

// The exact model matrix and the entrywise bound on raster's float one.
struct ModelMatrixError {
    glm::dmat4 exact{1.0};
    glm::dmat4 bound{0.0};
};

// One step of a chain: its exact matrix and the entrywise bound on raster's float one.
struct StepError {
    glm::dmat4 exact{1.0};
    glm::dmat4 bound{0.0};
};

// A step of the scene as raster holds it (a file's floats): the oracle's matrix of it and raster's error.
StepError raster_step_error(const TransformStep& step);

// The chain S_n ... S_1 of steps whose float matrices are off by their bounds, and raster's float product's bound
// (RASTER'S PRODUCT above).
ModelMatrixError raster_chain_error(const std::vector<StepError>& steps);

// The oracle's model matrix of `transform` and how far raster's can be from it.
ModelMatrixError raster_model_error(const ModelTransform& transform);

// |M| + bound: the magnitudes of raster's float matrix entries.
glm::dmat4 raster_model_magnitude(const ModelMatrixError& model);

// How far raster's clip position of object point `position` can be from the oracle's because its model matrix is
// off by `model.bound` (the rest, the camera's error and the products' roundings, is camera_precision.h's and
// precision.h's): |P_f| |V_f| bound |(p, 1)|, with |P_f| within gamma_3 of |P| and |V_f| within the camera's row
// and translation errors of |V|.
glm::dvec4 model_clip_error(const ModelMatrixError& model, const CameraMatrixError& camera_error,
                            const OracleCamera& camera, const glm::vec3& position);

// The entrywise bound on |inv(A_f) - inv(A)| for |A_f - A| <= bound (the first item of the inverse above), for a
// 3 x 3 or 4 x 4 A, and k = ||inv(A)| bound||_inf; infinite entries when k reaches 1/2.
template <typename Matrix>
struct InverseInputError {
    Matrix bound;
    double k = 0.0;
};
InverseInputError<glm::dmat3> inverse_input_error(const glm::dmat3& exact, const glm::dmat3& bound);
InverseInputError<glm::dmat4> inverse_input_error(const glm::dmat4& exact, const glm::dmat4& bound);

}  // namespace raster::oracle
