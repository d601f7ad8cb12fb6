// The shading error bounds; the derivations are next to the declarations in shading_precision.h.
#include "oracle/reference/shading_precision.h"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "oracle/reference/matrix_magnitude.h"
#include "oracle/reference/precision.h"

namespace raster::oracle {
namespace {

// |a| x| |b|: the componentwise magnitude of cross(a, b), its two products added.
glm::dvec3 cross_magnitude(const glm::dvec3& a, const glm::dvec3& b) {
    const glm::dvec3 x = glm::abs(a), y = glm::abs(b);
    return {x.y * y.z + x.z * y.y, x.z * y.x + x.x * y.z, x.x * y.y + x.y * y.x};
}

// How far a unit vector can move when the vector it normalises, of length `length`, moves by `change` (2-norm):
// 2 change / length plus the normalisation's own roundings; 2 (anything) when the change can reach the origin.
double unit_vector_error(double change, double length) {
    if (!(change < length)) return 2.0;
    return std::min(2.0, 2.0 * change / length + float_gamma(kNormalizeAttributeRoundings));
}

}  // namespace

glm::dvec3 raster_world_position_error(const ModelMatrixError& model, const glm::vec3& position) {
    const glm::dmat4 magnitude = raster_model_magnitude(model);
    const glm::dvec4 p = glm::abs(glm::dvec4(glm::dvec3(position), 1.0));
    glm::dvec3 error(0.0);
    for (int row = 0; row < 3; ++row) {
        double rounding = 0.0, input = 0.0;
        for (int k = 0; k < 4; ++k)
            if (p[k] > 0.0) {  // a zero coordinate adds an exact zero, however uncertain its column
                rounding += magnitude[k][row] * p[k];
                input += model.bound[k][row] * p[k];
            }
        error[row] = float_gamma(kWorldPositionRoundings) * rounding + input;
    }
    return error;
}

NormalMatrixError raster_normal_matrix_error(const ModelMatrixError& model) {
    NormalMatrixError out;
    const glm::dmat3 m(model.exact), bound(model.bound);
    const glm::dmat3 magnitude = absolute(m) + bound;  // |M_f|, the upper 3 x 3
    const InverseInputError<glm::dmat3> input_error = inverse_input_error(m, bound);  // inverse(M_f) against inverse(M)
    const glm::dmat3& input = input_error.bound;
    if (!std::isfinite(input[0][0])) return out;
    const double det = glm::determinant(m);
    const double det_floor = std::fabs(det) * std::pow(1.0 - std::min(input_error.k, 1.0), 3);
    // D, the magnitude of the determinant's expansion along the first column, and each minor's magnitude.
    double magnitude_d = 0.0;
    glm::dmat3 minor, minor_magnitude;  // minor[i][j] belongs to the inverse's entry (i, j) (glm: [column][row])
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) {
            // The cofactor of m's entry (row c, column r), which is the inverse's entry (row r, column c) times det.
            const int r0 = (c + 1) % 3, r1 = (c + 2) % 3, c0 = (r + 1) % 3, c1 = (r + 2) % 3;
            minor[c][r] = m[c0][r0] * m[c1][r1] - m[c1][r0] * m[c0][r1];
            minor_magnitude[c][r] = magnitude[c0][r0] * magnitude[c1][r1] + magnitude[c1][r0] * magnitude[c0][r1];
        }
    for (int r = 0; r < 3; ++r) magnitude_d += magnitude[0][r] * minor_magnitude[0][r];
    const double g_det = float_gamma(kDeterminantRoundings) * magnitude_d;
    if (!(g_det < det_floor)) return out;
    // The normal matrix is the inverse's transpose; its entry (row i, column j) is minor[i][j] / det.
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            out.entry[i][j] = minor[i][j] / det;
            out.magnitude[i][j] = std::fabs(out.entry[i][j]) + input[i][j];  // raster's inverse of its own M_f
            out.error[i][j] =
                (float_gamma(kMinorRoundings) * minor_magnitude[i][j] + out.magnitude[i][j] * g_det) /
                    (det_floor - g_det) +
                input[i][j];
        }
    out.bounded = true;
    return out;
}

double raster_file_normal_error(const NormalMatrixError& normal_matrix, const glm::vec3& normal) {
    if (!normal_matrix.bounded) return 2.0;
    glm::dvec3 exact(0.0), change(0.0);
    const glm::dvec3 n(normal);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            exact[i] += normal_matrix.entry[i][j] * n[j];
            change[i] += normal_matrix.error[i][j] * std::fabs(n[j]) +
                         float_gamma(3) * normal_matrix.magnitude[i][j] * std::fabs(n[j]);
        }
    return unit_vector_error(glm::length(change), glm::length(exact));
}

double raster_face_normal_error(const glm::dvec3 world[3], const glm::dvec3 error[3]) {
    const glm::dvec3 e1 = world[1] - world[0], e2 = world[2] - world[0];
    const glm::dvec3 de1 = error[1] + error[0] + kFloatUnitRoundoff * glm::abs(e1);
    const glm::dvec3 de2 = error[2] + error[0] + kFloatUnitRoundoff * glm::abs(e2);
    const glm::dvec3 dc = cross_magnitude(de1, glm::abs(e2) + de2) + cross_magnitude(e1, de2) +
                          float_gamma(kCrossRoundingsForNormals) * cross_magnitude(e1, e2);
    return unit_vector_error(glm::length(dc), glm::length(glm::cross(e1, e2)));
}

double raster_averaged_normal_error(const std::vector<glm::dvec3>& world, const std::vector<glm::dvec3>& position_error,
                                    const std::vector<TriangleIndices>& faces, uint32_t first_vertex) {
    glm::dvec3 sum(0.0);
    double change = 0.0;
    for (const TriangleIndices& face : faces) {
        glm::dvec3 corners[3], errors[3];
        for (int k = 0; k < 3; ++k) {
            corners[k] = world[first_vertex + face.v[k]];
            errors[k] = position_error[first_vertex + face.v[k]];
        }
        const glm::dvec3 cross = glm::cross(corners[1] - corners[0], corners[2] - corners[0]);
        const double length = glm::length(cross);
        if (length > 0.0) sum += cross / length;
        change += raster_face_normal_error(corners, errors);
    }
    const double faces_count = static_cast<double>(faces.size());
    change += float_gamma(static_cast<int>(faces.size())) * faces_count * std::sqrt(3.0);
    return unit_vector_error(change, glm::length(sum));
}

}  // namespace raster::oracle
