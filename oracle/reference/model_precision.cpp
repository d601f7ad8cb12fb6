// raster's float model matrix against the oracle's; the derivations are next to the declarations in
// model_precision.h.
#include "oracle/reference/model_precision.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <type_traits>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "oracle/reference/matrix_magnitude.h"
#include "oracle/reference/model_transform.h"
#include "oracle/reference/precision.h"

namespace raster::oracle {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

template <typename Matrix>
Matrix filled(double value) {
    Matrix a;
    for (int c = 0; c < a.length(); ++c)
        for (int r = 0; r < a.length(); ++r) a[c][r] = value;
    return a;
}

// How far raster's float matrix for `step` can be from the oracle's `exact`.
glm::dmat4 step_error(const TransformStep& step, const glm::dmat4& exact) {
    return std::visit(
        [&](const auto& s) -> glm::dmat4 {
            using Step = std::decay_t<decltype(s)>;
            glm::dmat4 error(0.0);
            if constexpr (std::is_same_v<Step, RotateStep>) {
                const double radians = std::fabs(double(s.degrees)) * std::numbers::pi / 180.0;
                const double in_double = (kRotateDoubleRoundings + 3.0 * radians) * 0x1p-53;
                for (int c = 0; c < 3; ++c)
                    for (int r = 0; r < 3; ++r)
                        error[c][r] = kFloatUnitRoundoff * (std::fabs(exact[c][r]) + in_double) + in_double;
            } else if constexpr (std::is_same_v<Step, QuaternionStep>) {
                const double dq = float_gamma(kQuaternionNormalizeRoundings);
                const double entry = 4.0 * dq + 2.0 * dq * dq + 3.0 * float_gamma(kQuaternionEntryRoundings) +
                                     double_gamma(16);
                for (int c = 0; c < 3; ++c)
                    for (int r = 0; r < 3; ++r) error[c][r] = entry;
            } else if constexpr (std::is_same_v<Step, LookAtStep>) {
                const Camera frame = look_at_camera(s);
                const CameraMatrixError basis = raster_camera_error(frame, oracle_camera(frame, 1, 1));
                for (int c = 0; c < 3; ++c)  // the columns are right, up and back
                    for (int r = 0; r < 3; ++r) error[c][r] = basis.row[c];
            }
            return error;  // translate, scale and matrix steps: the file's floats, exact
        },
        step);
}

// One step of raster's product: the bound after P' = S P, from |P_f - P| <= bound and |S_f - S| <= step_bound.
glm::dmat4 product_bound(const glm::dmat4& s, const glm::dmat4& step_bound, const glm::dmat4& p,
                         const glm::dmat4& bound) {
    const glm::dmat4 abs_s = absolute(s), abs_p = absolute(p);
    glm::dmat4 out = abs_s * bound + step_bound * abs_p + step_bound * bound +
                     float_gamma(kProductRoundings) * ((abs_s + step_bound) * (abs_p + bound)) +
                     double_gamma(kProductRoundings) * (abs_s * abs_p);
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (std::isnan(out[c][r])) out[c][r] = kInfinity;  // 0 * inf: nothing is certain
    return out;
}

ModelMatrixError chain_error(const std::vector<TransformStep>& steps) {
    std::vector<StepError> errors;
    for (const TransformStep& step : steps) errors.push_back(raster_step_error(step));
    return raster_chain_error(errors);
}

// The permanent of the 3 x 3 minor of non-negative `m` without column `skip_c` and row `skip_r`: the sum of the
// magnitudes of the six products a cofactor expansion adds.
double minor_permanent(const glm::dmat4& m, int skip_c, int skip_r) {
    int cols[3], rows[3];
    for (int i = 0, c = 0, r = 0; i < 4; ++i) {
        if (i != skip_c) cols[c++] = i;
        if (i != skip_r) rows[r++] = i;
    }
    auto at = [&](int c, int r) { return m[cols[c]][rows[r]]; };
    return at(0, 0) * (at(1, 1) * at(2, 2) + at(2, 1) * at(1, 2)) + at(1, 0) * (at(0, 1) * at(2, 2) + at(2, 1) * at(0, 2)) +
           at(2, 0) * (at(0, 1) * at(1, 2) + at(1, 1) * at(0, 2));
}

// raster's float inverse of the chain C (exact `chain.exact`, raster's within `chain.bound`): the inverse and the
// bound on raster's.
ModelMatrixError inverse_error(const ModelMatrixError& chain) {
    ModelMatrixError out;
    out.exact = glm::inverse(chain.exact);
    const InverseInputError<glm::dmat4> input_error = inverse_input_error(chain.exact, chain.bound);
    const glm::dmat4& input = input_error.bound;
    const double k = input_error.k;
    const double det_floor = std::fabs(glm::determinant(chain.exact)) * std::pow(1.0 - std::min(k, 1.0), 4);
    const glm::dmat4 magnitude = absolute(chain.exact) + chain.bound;  // |C_f|
    double permanent = 0.0;  // D: the first column's expansion
    for (int r = 0; r < 4; ++r) permanent += magnitude[0][r] * minor_permanent(magnitude, 0, r);
    const double g2 = float_gamma(2), g5 = float_gamma(kCofactorRoundings);
    const double det_noise = float_gamma(kInverseDeterminantRoundings) * permanent;
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) {
            const double inverse = std::fabs(out.exact[c][r]) + input[c][r];
            // The inverse's entry (row r, column c) is the cofactor of C's entry (row c, column r) over det.
            const double arithmetic =
                det_noise < det_floor
                    ? (1.0 + g2) * (g5 * minor_permanent(magnitude, r, c) + inverse * det_noise) / (det_floor - det_noise) +
                          g2 * inverse
                    : kInfinity;
            out.bound[c][r] = input[c][r] + arithmetic;
        }
    return out;
}

template <typename Matrix>
InverseInputError<Matrix> inverse_input_error_of(const Matrix& exact, const Matrix& bound) {
    const Matrix inverse = absolute(glm::inverse(exact));
    const Matrix f = inverse * bound;
    const double k = largest_row_sum(f);
    if (!(k < 0.5)) return {filled<Matrix>(kInfinity), k};
    const Matrix first = f * inverse;
    return {first + filled<Matrix>(k * largest_entry(first) / (1.0 - k)), k};
}

}  // namespace

StepError raster_step_error(const TransformStep& step) {
    const glm::dmat4 exact = oracle_step_matrix(step);
    return {exact, step_error(step, exact)};
}

ModelMatrixError raster_chain_error(const std::vector<StepError>& steps) {
    ModelMatrixError chain;
    for (const StepError& step : steps) {
        chain.bound = product_bound(step.exact, step.bound, chain.exact, chain.bound);
        chain.exact = step.exact * chain.exact;
    }
    return chain;
}

InverseInputError<glm::dmat3> inverse_input_error(const glm::dmat3& exact, const glm::dmat3& bound) {
    return inverse_input_error_of(exact, bound);
}
InverseInputError<glm::dmat4> inverse_input_error(const glm::dmat4& exact, const glm::dmat4& bound) {
    return inverse_input_error_of(exact, bound);
}

ModelMatrixError raster_model_error(const ModelTransform& transform) {
    ModelMatrixError model = chain_error(transform.steps);
    if (transform.then_inverse_of.empty()) return model;
    const ModelMatrixError view = inverse_error(chain_error(transform.then_inverse_of));
    ModelMatrixError out;
    out.bound = product_bound(view.exact, view.bound, model.exact, model.bound);
    out.exact = view.exact * model.exact;
    return out;
}

glm::dmat4 raster_model_magnitude(const ModelMatrixError& model) { return absolute(model.exact) + model.bound; }

glm::dvec4 model_clip_error(const ModelMatrixError& model, const CameraMatrixError& camera_error,
                            const OracleCamera& camera, const glm::vec3& position) {
    glm::dvec4 offset(0.0);  // bound |(p, 1)|, leaving out the columns p does not reach
    const glm::dvec4 p = glm::abs(glm::dvec4(glm::dvec3(position), 1.0));
    for (int k = 0; k < 4; ++k)
        if (p[k] > 0.0) offset += model.bound[k] * p[k];
    glm::dmat4 view = absolute(camera.view);
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) view[c][r] += camera_error.row[r];
        view[3][r] += camera_error.translation[r];
    }
    glm::dvec4 clip = (1.0 + float_gamma(kProjectionRoundings)) * (absolute(camera.projection) * (view * offset));
    for (int i = 0; i < 4; ++i)
        if (std::isnan(clip[i])) clip[i] = kInfinity;  // an unbounded entry times a zero: nothing is certain
    return clip;
}

}  // namespace raster::oracle
