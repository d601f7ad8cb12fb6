// A model transform's magnitude: a bound on its product's entries from each step's values.
#include "raster/scene/model_transform.h"

#include <algorithm>
#include <cmath>
#include <type_traits>

namespace raster {
namespace {

double largest(const glm::vec3& v) { return std::max({std::fabs(double(v.x)), std::fabs(double(v.y)), std::fabs(double(v.z))}); }

// The largest row sum of |S| for one step, bounded from its values (a rotation's rows are unit vectors: at most
// sqrt 3 each; a look-at's 3 x 3 part likewise, and its translation is the eye).
double step_magnitude(const TransformStep& step) {
    constexpr double kUnitRowSum = 1.7320508075688772 + 1e-12;
    return std::visit(
        [&](const auto& s) -> double {
            using Step = std::decay_t<decltype(s)>;
            if constexpr (std::is_same_v<Step, TranslateStep>) return 1.0 + largest(s.offset);
            else if constexpr (std::is_same_v<Step, ScaleStep>) return std::max(1.0, largest(s.factors));
            else if constexpr (std::is_same_v<Step, RotateStep> || std::is_same_v<Step, QuaternionStep>)
                return kUnitRowSum;
            else if constexpr (std::is_same_v<Step, LookAtStep>) return kUnitRowSum + largest(s.eye);
            else {
                double rows = 0.0;
                for (int r = 0; r < 4; ++r) {
                    double sum = 0.0;
                    for (int c = 0; c < 4; ++c) sum += std::fabs(double(s.matrix[c][r]));
                    rows = std::max(rows, sum);
                }
                return rows;
            }
        },
        step);
}

}  // namespace

double model_magnitude_bound(const std::vector<TransformStep>& steps) {
    double bound = 1.0;
    for (const TransformStep& step : steps) bound *= step_magnitude(step);
    return bound;
}

}  // namespace raster
