// The generators of whole scenes at the extremes: two quads over near = 1e-6 to far = 1e9, and a scene scaled
// towards the float limits.
#include "properties/generators/scene_extremes.h"

#include <algorithm>
#include <cmath>

#include "properties/generators/primitives.h"
#include "properties/printing.h"

namespace raster::properties {

std::ostream& operator<<(std::ostream& os, const DepthPairCase& c) {
    return os << "DepthPairCase{\"" << c.kind << "\", " << float_literal(c.near_depth) << ", "
              << float_literal(c.far_depth) << ", " << (c.nearer_first ? "true" : "false") << "}";
}

std::ostream& operator<<(std::ostream& os, const ScaledSceneCase& c) {
    return os << "ScaledSceneCase{\"" << c.kind << "\", " << c.exponent << ", {" << literal(c.triangle[0]) << ", "
              << literal(c.triangle[1]) << ", " << literal(c.triangle[2]) << "}, " << literal(c.eye) << ", "
              << literal(c.target) << ", " << float_literal(c.near) << ", " << float_literal(c.far) << "}";
}

Gen<DepthPairCase> depth_pairs_over_extreme_range() {
    return gen::exec([] {
        const double near = 1e-6, far = 1e9, gap = std::ldexp(1.0, -19);
        const int kind = *gen::weightedElement<int>({{3, 0}, {1, 1}, {1, 2}, {1, 3}});
        double a = log_uniform(near, far / (1.0 + 4 * gap)), b = a * log_uniform(1.0 + 2 * gap, far / a);
        if (kind == 1) a = near, b = near * log_uniform(1.0 + 2 * gap, 10.0);
        if (kind == 2) b = far, a = far / log_uniform(1.0 + 2 * gap, 10.0);
        if (kind == 3) b = a * (1.0 + gap * (2.0 + 2.0 * unit()));
        const float fa = static_cast<float>(a);
        float fb = static_cast<float>(std::min(b, far));
        if (!(double(fb) >= double(fa) * (1.0 + gap))) fb = std::nextafter(static_cast<float>(double(fa) * (1.0 + 2 * gap)), INFINITY);
        const char* names[] = {"anywhere", "at the near plane", "at the far plane", "2^-19 apart"};
        return DepthPairCase{names[kind], fa, std::min(fb, 1e9f), coin()};
    });
}

Gen<ScaledSceneCase> scenes_scaled_towards_float_limits() {
    return gen::exec([] {
        ScaledSceneCase c;
        // Exactness of the scaling (derived in the property): every intermediate stays a normal float when
        // 2^-100 * 2^-8 and 20 * 2.5 * 2^120 are representable, and 1 / (20 * 2^120) is still normal.
        c.exponent = *gen::weightedOneOf<int>({{2, uniform(80, 120)}, {1, uniform(-100, -60)}, {1, uniform(-10, 10)}});
        c.kind = c.exponent >= 80 ? "scaled towards FLT_MAX" : c.exponent <= -60 ? "scaled towards FLT_MIN" : "moderate";
        auto grid = [](double lo, double hi) {
            return static_cast<float>(std::ldexp(std::round(std::ldexp(lo + (hi - lo) * unit(), 8)), -8));
        };
        for (auto& p : c.triangle) p = {grid(-4, 4), grid(-4, 4), grid(-16, -1)};
        c.eye = glm::vec3(0.0f);
        c.target = {0.0f, 0.0f, -1.0f};
        c.near = 0.5f;
        c.far = 20.0f;
        return c;
    });
}

}  // namespace raster::properties
