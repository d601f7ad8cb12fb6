// The light generator: a surface normal, a direction towards the light in front of it, a distance and a colour.
#include "properties/generators/lights.h"

#include <glm/geometric.hpp>

#include "properties/generators/primitives.h"
#include "properties/printing.h"

namespace raster::properties {

std::ostream& operator<<(std::ostream& os, const LightCase& c) {
    return os << "LightCase{\"" << c.kind << "\", " << literal(c.normal) << ", " << literal(c.direction) << ", "
              << float_literal(c.distance) << ", " << literal(c.color) << "}";
}

Gen<LightCase> lights() {
    return gen::exec([] {
        LightCase c;
        c.normal = random_direction();
        c.direction = *gen::suchThat(gen::exec([] { return random_direction(); }),
                                     [normal = c.normal](const glm::vec3& d) { return glm::dot(d, normal) > 0.1f; });
        const int kind = *gen::weightedElement<int>({{4, 0}, {1, 1}, {1, 2}});
        c.distance = kind == 0 ? static_cast<float>(log_uniform(0.1, 100.0)) : kind == 1 ? 1e-3f : 1e3f;
        c.kind = kind == 0 ? "random distance" : kind == 1 ? "1e-3 away" : "1e3 away";
        c.color = {static_cast<float>(0.1 + unit()), static_cast<float>(0.1 + unit()), static_cast<float>(0.1 + unit())};
        return c;
    });
}

}  // namespace raster::properties
