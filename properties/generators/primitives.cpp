// The draws every generator is built from: uniform integers, units, log-uniform reals, coins, vectors,
// directions and permutations, at full size whatever RapidCheck's current size.
#include "properties/generators/primitives.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace raster::properties {

double unit() { return std::ldexp(static_cast<double>(*uniform<int64_t>(0, (int64_t{1} << 24) - 1)), -24); }

double log_uniform(double lo, double hi) { return lo * std::pow(hi / lo, unit()); }

bool coin() { return *uniform<int>(0, 1) == 1; }

double signed_unit() { return 2.0 * unit() - 1.0; }

glm::vec3 random_vector(double scale) {
    return {static_cast<float>(scale * signed_unit()), static_cast<float>(scale * signed_unit()),
            static_cast<float>(scale * signed_unit())};
}

glm::vec3 random_direction() {
    const double z = signed_unit(), phi = 2.0 * kPi * unit(), r = std::sqrt(std::max(0.0, 1.0 - z * z));
    return {static_cast<float>(r * std::cos(phi)), static_cast<float>(r * std::sin(phi)), static_cast<float>(z)};
}

Gen<std::vector<int>> permutations(int n) {
    return gen::exec([n] {
        std::vector<int> order(static_cast<size_t>(n));
        std::iota(order.begin(), order.end(), 0);
        for (int i = n - 1; i > 0; --i) std::swap(order[static_cast<size_t>(i)], order[static_cast<size_t>(*uniform(0, i))]);
        return order;
    });
}

}  // namespace raster::properties
