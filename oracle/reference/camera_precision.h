// The precision model, part 2b: how far raster's float camera matrices can be from the oracle's exact camera
// (camera.h), so that the clip-space vertex error of precision.h section 2 covers a raster whose view and
// projection were built in float from the same Camera. Each bound is derived next to its constant.
#pragma once

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "oracle/reference/camera.h"
#include "raster/scene/scene.h"

namespace raster::oracle {

// RASTER'S VIEW MATRIX. raster builds the basis in float from the float eye, target and up (norms are 2-norms):
//  - back = normalize(eye - target): the difference rounds each component once (the direction moves by at most
//    2u), the squared length is a 3-term sum of squares (gamma_3, relative), the inverse square root and the
//    scaling add 3 roundings: |back_f - back| <= gamma_5 + 2u <= gamma_7 =: E_back;
inline constexpr int kViewBackRoundings = 7;
//  - c = cross(up, back_f): exact with back_f it is off by |up| E_back; its float evaluation by 2 gamma_2 |up|
//    (1 + E_back) (two products and a difference per component). Then right = normalize(c): a unit vector moves by
//    at most 2 |dc| / |c|, with |c| = |up| sin(theta), theta the angle between up and the exact back, and the
//    normalisation adds gamma_5: E_right = 2 (E_back + 2 gamma_2 (1 + E_back)) / sin(theta) + gamma_5. Near a
//    parallel up this grows without bound: raster's basis is then as uncertain as the scene makes it;
inline constexpr int kCrossRoundings = 2;
inline constexpr int kNormalizeRoundings = 5;
//  - up' = cross(back_f, right_f), not normalised: E_up = E_back + E_right + E_back E_right + 2 gamma_2 (1 +
//    E_back)(1 + E_right);
//  - the translation -dot(row_f, eye), a 3-term float dot product: off by E_row |eye| + gamma_3 (1 + E_row) |eye|.
// So raster's view-space point for a world point q is, per row i, within E_row_i |q| + E_translation_i of exact.
//
// RASTER'S PROJECTION MATRIX is computed in double from the float field of view, near and far and rounded to
// float once per entry; aspect = float(width) / float(height) adds one rounding to the first entry: every entry
// is within gamma_3 (relative) of the oracle's (double's own error, < 1e-15, is inside the third rounding). An
// orthographic matrix is built the same way from the float height, near and far, and its w row (0 0 0 1) is exact.
inline constexpr int kProjectionRoundings = 3;

struct CameraMatrixError {
    glm::dvec3 row{0.0};          // right, up, back: how far each of raster's basis rows can be from exact
    glm::dvec3 translation{0.0};  // the same for the translation column
    double projection = 0.0;      // relative, every entry of P
};

// The bounds above for the scene's float `camera`, whose exact counterpart is `exact`.
CameraMatrixError raster_camera_error(const Camera& camera, const OracleCamera& exact);

// How far raster's clip-space position of world point `world`, transformed by its float P V (before the
// products' own roundings, which precision.h section 2 counts), can be from the oracle's exact P V world:
//     |P_f V_f q - P V q| <= gamma_3 |P| (|V q| + e) + |P| e,    e = view-space error of the rows above.
glm::dvec4 camera_clip_error(const CameraMatrixError& error, const OracleCamera& exact, const glm::dvec3& world);

}  // namespace raster::oracle
